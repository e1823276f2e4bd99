// FastMove.h - two cures for tunnelling, on plain values (no SFML).
//
// A bullet (an upright box) flies along x at a thin wall. A plain discrete step moves it
// by velocity * dt and then asks "do they overlap now?": at a high enough speed it jumps
// from one side of the wall to the other between two questions, and never hits it.
// Units: pixels and seconds. Touching is not overlapping (Hitbox's edge rule).
#pragma once

#include "hitbox/geometry/Shapes.h"

// Boxes are Hitbox's hitbox::Box (hitbox/geometry/Shapes.h): left, top, width, height; its
// right side is hitbox::rightOf(box), its bottom hitbox::bottomOf(box).
using hitbox::Box;

// Where one step left the bullet: its box, whether it hit the wall, and how many
// overlap tests the step ran.
struct MoveResult
{
    Box bullet;
    bool hitWall = false;
    int overlapTests = 0;
};

// Given: the box moved by dx along x. (Whether two boxes share area is Hitbox's
// hitbox::boxVsBox, hitbox/geometry/Overlap.h: touching does not count.)
Box movedBy(const Box& box, float dx);

// Given: the plain discrete step: move the whole way, then one overlap test. On a hit, the
// bullet is put back against the wall's near side.
MoveResult discreteStep(const Box& bullet, float velocityX, float dt, const Box& wall);

// Task 1: the same step cut into sub-steps, none longer than `maxSubStep` pixels, with an
// overlap test after each; stops at the first hit, against the wall's near side.
MoveResult subSteppedStep(const Box& bullet, float velocityX, float dt, const Box& wall,
                          float maxSubStep);
// Task 2: a speculative contact: before moving, measure the gap to the wall ahead; if this
// step's move would cross it, move only as far as the gap (ending touching) and report the
// hit. One test, no overlap ever, at any speed.
MoveResult speculativeStep(const Box& bullet, float velocityX, float dt, const Box& wall);
