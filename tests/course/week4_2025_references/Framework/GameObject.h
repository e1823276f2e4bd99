// A stale copy of the course's 2025 framework, as lab folders carry it: its m_ members tell
// Hitbox which generation the lab is. Hitbox must ignore it; if the build reads it, it stops.
//   sf::Vector2f m_velocity;  sf::FloatRect m_collisionBox;
#error "tests/course: the lab's own Framework/ copy was compiled; Hitbox should have ignored it"
