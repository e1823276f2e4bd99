// FastMove.h - two cures for tunnelling, on plain values (no SFML).
//
// A bullet (an upright box) flies along x at a thin wall. A plain discrete step moves it
// by velocity * dt and then asks "do they overlap now?": at a high enough speed it jumps
// from one side of the wall to the other between two questions, and never hits it.
// Units: pixels and seconds. Touching is not overlapping (Hitbox's edge rule).
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <vector>

// Boxes are Hitbox's hitbox::Box (hitbox/geometry/Shapes.h): left, top, width, height; its
// right side is hitbox::rightOf(box), its bottom hitbox::bottomOf(box).
using hitbox::Box;

// Where one step left the bullet, and whether it hit the wall.
struct MoveResult
{
    Box bullet;
    bool hitWall = false;
};

// Given (Given.cpp, with everything else marked "Given"): the wall and its overlap test,
// counted. Each test remembers the bullet's box it was asked about, so the tests (and you)
// can see where every test of a step ran.
class WallTests
{
public:
    explicit WallTests(const Box& box);
    // The wall's box.
    [[nodiscard]] const Box& box() const;
    // Does `bullet` overlap the wall? Strict: touching does not (Hitbox's hitbox::boxVsBox,
    // hitbox/geometry/Overlap.h). Counts one test and remembers the box.
    bool overlaps(const Box& bullet);
    // The bullet's box at every test so far, in order; its size is the count.
    [[nodiscard]] const std::vector<Box>& tested() const;

private:
    Box wallBox;
    std::vector<Box> testedBoxes;
};

// Given: the box moved by dx along x.
[[nodiscard]] Box movedBy(const Box& box, float dx);
// Given: the bullet put back against the side of the wall it came from (moving right: its
// right side on the wall's left side).
[[nodiscard]] Box againstWall(const Box& bullet, float velocityX, const Box& wall);

// Given: the plain discrete step: move the whole way, then one overlap test. On a hit, the
// bullet is put back against the wall's near side.
MoveResult discreteStep(const Box& bullet, float velocityX, float dt, WallTests& wall);

// Task 1: the same step cut into sub-steps, none longer than `maxSubStep` pixels, with an
// overlap test (`wall.overlaps`) after each; stops at the first hit, against the wall's near
// side.
MoveResult subSteppedStep(const Box& bullet, float velocityX, float dt, WallTests& wall,
                          float maxSubStep);
// Task 2: a speculative contact: before moving, measure the gap to the wall ahead; if this
// step's move would cross it, move only as far as the gap (ending touching) and report the
// hit. No overlap test and no loop: one gap measured, no overlap ever, at any speed.
MoveResult speculativeStep(const Box& bullet, float velocityX, float dt, const Box& wall);
