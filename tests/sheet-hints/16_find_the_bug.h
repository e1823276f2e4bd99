// Lab 16's hints are written inside Bugs.cpp: in PressurePlate's members (standingOn, the
// event) and in inGateway (gateway, thing).
#pragma once
#include "Bugs.h"
#include "Pieces.h"

#include "hitbox/geometry/Explain.h"

#include <iostream>

struct HintScope
{
    void hints();
    int standingOn = 0;
    hitbox::CollisionEvent event;
    hitbox::Box gateway, thing;
};
