// Bugs.h - lab 16's three functions with a bug each (Bugs.cpp), one a task: the plate that
// never lets go, the doorway that counts touching, the crates that outlive their step.
#pragma once

#include "Pieces.h"

#include "hitbox/geometry/Shapes.h"
#include "hitbox/objects/World.h"

#include <memory>
#include <vector>

// Task 1 is PressurePlate's four members (Pieces.h).

// Task 2: true when `thing` is in the gateway (shares area with it); the gate closes only
// when nothing is. Touching is not being in it: Hitbox's rule for every collision.
[[nodiscard]] bool inGateway(const hitbox::Box& gateway, const hitbox::Box& thing);

// Task 3: takes every delivered crate out of `world`, then destroys it; returns how many. The
// crates that stay keep their order.
int removeDelivered(hitbox::World& world, std::vector<std::unique_ptr<Crate>>& crates);
