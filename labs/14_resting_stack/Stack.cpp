#include "Stack.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

void pushApart(std::vector<Crate>& crates, const std::vector<Contact>& contacts)
{
    // BEGIN TASK 1: push every crate out by the measured depths
    // Every push uses the depth measured before any push: that is what makes one pass
    // over-correct a crate caught between two contacts.
    for (const Contact& contact : contacts)
    {
        Crate& above = crates[static_cast<std::size_t>(contact.above)];
        if (contact.below == floorIndex)
        {
            // The floor does not move: the crate goes up the whole depth and stops falling.
            above.top -= contact.depth;
            above.velocityY = std::min(above.velocityY, 0.f);
            continue;
        }
        Crate& below = crates[static_cast<std::size_t>(contact.below)];
        above.top -= contact.depth / 2.f;
        below.top += contact.depth / 2.f;
        // Closing (the upper crate falls faster): both go on at their average speed, an
        // inelastic contact; crates already moving apart are left alone.
        if (above.velocityY > below.velocityY)
        {
            const float average = (above.velocityY + below.velocityY) / 2.f;
            above.velocityY = average;
            below.velocityY = average;
        }
    }
    // STARTER TASK 1
    // (void)crates;
    // (void)contacts;
    // END TASK 1
}

int resolvePenetrations(std::vector<Crate>& crates, float floorY, int passes, PushApart push)
{
    // BEGIN TASK 2: pass after pass, measure again and push again
    // Each pass measures the contacts where the last pass left the crates, so the
    // corrections of one contact reach its neighbours; a few passes let a stack rest.
    int pushed = 0;
    while (pushed < passes)
    {
        const std::vector<Contact> contacts = findContacts(crates, floorY);
        if (contacts.empty())
            break; // nothing overlaps any more: further passes would change nothing
        push(crates, contacts);
        ++pushed;
    }
    return pushed;
    // STARTER TASK 2
    // (void)passes;
    // push(crates, findContacts(crates, floorY)); // one pass, whatever `passes` says: it shakes
    // return 1;
    // END TASK 2
}
