// A stale copy of the course's 2025 framework, as lab folders carry it (m_ members:
// sf::Vector2f m_velocity;). Hitbox must ignore it; if the build reads it, it stops here.
#error "tests/course: the lab's own Framework/ copy was compiled; Hitbox should have ignored it"
