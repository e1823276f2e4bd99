// Lab 4's hints are written inside PaperLevel's tests (PaperLevel.cpp), on hitbox::Box values.
#pragma once
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"

struct HintScope
{
    void hints();
    hitbox::Box a, b, box, wall;
    hitbox::Vec2 step;
};
