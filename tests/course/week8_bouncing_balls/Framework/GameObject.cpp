// A stale copy of the course's old framework source. Hitbox must not compile it.
#error "tests/course: the lab's old Framework/GameObject.cpp was compiled; Hitbox should have ignored it"
