#include "Ball.h"

void bounceApart(Ball& a, Ball& b, const hitbox::Contact& contact)
{
    // Splitting the push equally leaves them exactly touching, which the edge rule does
    // not count as a collision: no sticking next step.
    const hitbox::Vec2 push = contact.normal * (contact.depth / 2.f);
    a.position += push;
    b.position -= push;

    // Closing speed along the normal. Already separating: leave the velocities alone, or
    // balls that were pushed into each other by a third one would be pulled back together.
    const float closing = hitbox::dot(a.velocity - b.velocity, contact.normal);
    if (closing < 0.f)
    {
        a.velocity -= contact.normal * closing;
        b.velocity += contact.normal * closing;
    }
    ++a.responses;
    ++b.responses;
}
