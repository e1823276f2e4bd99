// A stale copy of the course's 2025 framework: keys by sf::Keyboard::Scancode. Hitbox must
// ignore it; if the build reads it, it stops here.
#error "tests/course: the lab's own Framework/ copy was compiled; Hitbox should have ignored it"
