// Stack.h - crates resting on each other, pushed out of each other pass by pass (no SFML).
//
// Every step gravity pulls each crate a little into the crate below it, or into the floor;
// then the penetrations are resolved: every contact is measured, then every crate is pushed
// out by what was measured. A crate between two contacts gets two pushes measured before
// either happened, so one pass over-corrects: a tall stack sinks into itself and shakes from
// step to step (the jitter problem). Measuring again and pushing again, a few passes a step,
// lets it rest (Millington, Game Physics Engine Development, "Hard constraints": resolving
// interpenetration with an iterative contact resolver).
// Units: pixels, seconds; y grows downwards. Touching is not overlapping (Hitbox's edge rule).
#pragma once

#include <vector>

constexpr float gravity = 980.f; // pixels per second per second, downwards
constexpr int floorIndex = -1;   // Contact::below for a crate on the floor

// A square crate: its top-left corner, its side, and how fast it falls.
struct Crate
{
    float left = 0.f;
    float top = 0.f;
    float size = 50.f;
    float velocityY = 0.f; // pixels per second, positive is down
};

// One crate reaching into the crate below it (or the floor), measured before any push.
struct Contact
{
    int above = 0;          // index of the upper crate
    int below = floorIndex; // index of the lower crate, or floorIndex
    float depth = 0.f;      // pixels of vertical overlap, always > 0
};

// Given (Given.cpp): gravity for one step: each crate speeds up and moves down.
void fall(std::vector<Crate>& crates, float dt);
// Given: every crate reaching strictly into another (their x ranges and y ranges overlap)
// or below the floor line `floorY`. Crates that only touch make no contact.
std::vector<Contact> findContacts(const std::vector<Crate>& crates, float floorY);
// Given: the deepest contact now (0 when nothing overlaps).
float deepestOverlap(const std::vector<Crate>& crates, float floorY);
// Given: the largest distance any crate moved between `before` and `after` (same crates).
float largestMove(const std::vector<Crate>& before, const std::vector<Crate>& after);

// Task 1: one pass of responses: push every crate out by the depths measured in `contacts`.
// On the floor: up by the whole depth, and it stops falling. Between two crates: each moves
// half the depth apart, and if they were closing they go on at their average speed.
void pushApart(std::vector<Crate>& crates, const std::vector<Contact>& contacts);

// The response one pass uses: the lab passes pushApart (task 1); the grading tests of task 2
// pass their own, so a mistake in task 1 never costs task 2.
using PushApart = void (*)(std::vector<Crate>& crates, const std::vector<Contact>& contacts);

// Task 2: up to `passes` passes of "find the contacts, push them apart"; stops early when no
// contact is left. Returns how many passes pushed something.
int resolvePenetrations(std::vector<Crate>& crates, float floorY, int passes,
                        PushApart push = pushApart);
