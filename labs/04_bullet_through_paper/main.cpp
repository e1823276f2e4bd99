// Lab 4 - Bullet through paper
// Teaches: why a discrete test (is it overlapping NOW?) misses fast objects, and how a swept
// test (what did the whole move touch?) never does. The same shot flies down two lanes at
// rising speeds; the scoreboard counts the misses.
// Keys: Space fire, Up/Down next speed, A auto-fire on/off, plus the shared keys
// (F1 shows the swept area of each step: orange when the step could tunnel).
#include "PaperLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 4 - Bullet through paper"},
                       [](const hitbox::Options&) { return std::make_unique<PaperLevel>(); });
}
