// Lab 13 - Fast movers: sub-steps and speculative contacts
// Teaches: why a plain discrete step lets a fast bullet through a thin wall, and two cures
// that keep the fixed step: cut the move into sub-steps no longer than the wall is thick,
// or measure the gap ahead first and move no further (a speculative contact).
// Keys: none of its own (it fires by itself, faster every shot, up to a top speed); F1 the
// next moves, sub-steps and measured gaps, P pause, N step, F12
// screenshot. The tasks are in README.md.
#include "RangeLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 13 - Fast movers"},
                       [](const hitbox::Options&) { return std::make_unique<RangeLevel>(); });
}
