// A stale copy of the course's old framework, as lab folders carry it. Hitbox must ignore
// this folder (its own compat headers take its place); if the build ever reads this file,
// it stops here.
#error "tests/course: the lab's old Framework/ copy was compiled; Hitbox should have ignored it"
