// Lab 11's hints are written inside Paddle::moveWithinCourt (task 1) and moveBall (task 5).
#pragma once
#include "Court.h"
#include "Paddle.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/sfml/Conversions.h"

struct HintScope : Paddle
{
    void hints();
    hitbox::Box box; // task 1: the hint before declares it as hitbox::toBox(getCollisionBox())
    hitbox::Hit hit; // task 5: the earliest sweep's result
};
