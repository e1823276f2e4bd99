// Lab 14 - Resting stack: iterative penetration resolution
// Teaches: why resolving every contact once a step makes a tall stack sink and shake (the
// jitter problem: a crate between two contacts is over-corrected), and the cure: measure the
// contacts again and push again, a few passes a step, until the stack rests.
// Keys: Up/Down change the right stack's passes a step (the left one always gets 1), R
// restacks; plus F1 debug boxes (hatched vermillion: overlapping; dashed yellow: resting,
// up to StackLevel::restingSlop deep) and velocity arrows, P pause, N step,
// F12 screenshot. The tasks are in README.md.
#include "StackLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 14 - Resting stack"},
                       [](const hitbox::Options&) { return std::make_unique<StackLevel>(); });
}
