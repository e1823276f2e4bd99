#include "hitbox/geometry/Tunnelling.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Vec2.h"

#include <cmath>

namespace hitbox
{
namespace
{

Box movedBy(Box box, Vec2 offset)
{
    box.left += offset.x;
    box.top += offset.y;
    return box;
}

// The smallest box holding the mover at the start and at the end of the step: for a box
// moving in a straight line, everywhere between too (the swept-bounds broad phase).
Box sweptBounds(const Box& box, Vec2 displacement)
{
    const Box start = normalised(box);
    const Box end = movedBy(start, displacement);
    const float left = std::fmin(start.left, end.left);
    const float top = std::fmin(start.top, end.top);
    const float right = std::fmax(rightOf(start), rightOf(end));
    const float bottom = std::fmax(bottomOf(start), bottomOf(end));
    return {left, top, right - left, bottom - top};
}

} // namespace

// [slide:tunnelling-check]
bool canTunnel(const Box& moverBox, Vec2 displacement, const Box& targetBox)
{
    if (!isFinite(moverBox) || !isFinite(displacement) || !isFinite(targetBox))
        return false;
    const Box mover = normalised(moverBox);
    const Box target = normalised(targetBox);
    // To get from touching one side to touching the other, the mover travels its own size
    // plus the target's. A step at least that long can jump the target completely.
    const bool longEnough = std::fabs(displacement.x) >= mover.width + target.width ||
                            std::fabs(displacement.y) >= mover.height + target.height;
    // Broad phase: the target must lie where this step could take the mover.
    return longEnough && boxVsBox(sweptBounds(mover, displacement), target);
}
// [/slide]

} // namespace hitbox
