// Given.cpp - the code given to you in lab 14: gravity, finding the contacts, and the two
// measures of a settled stack. Yours is Stack.cpp. The grading tests drop and measure the
// stacks with this file, so the grader always uses the course's copy of it: a change here
// changes nothing there.
#include "Stack.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

void fall(std::vector<Crate>& crates, float dt)
{
    for (Crate& crate : crates)
    {
        crate.velocityY += gravity * dt;
        crate.top += crate.velocityY * dt;
    }
}

std::vector<Contact> findContacts(const std::vector<Crate>& crates, float floorY)
{
    std::vector<Contact> contacts;
    const int count = static_cast<int>(crates.size());
    for (int index = 0; index < count; ++index)
    {
        const Crate& crate = crates[static_cast<std::size_t>(index)];
        if (crate.top + crate.size > floorY)
            contacts.push_back({index, floorIndex, crate.top + crate.size - floorY});
    }
    for (int first = 0; first < count; ++first)
    {
        for (int second = first + 1; second < count; ++second)
        {
            const Crate& a = crates[static_cast<std::size_t>(first)];
            const Crate& b = crates[static_cast<std::size_t>(second)];
            const bool levelInX = a.left < b.left + b.size && b.left < a.left + a.size;
            const bool levelInY = a.top < b.top + b.size && b.top < a.top + a.size;
            if (!levelInX || !levelInY)
                continue;
            // The crate whose top is higher is the one above; the overlap is vertical only.
            const bool firstAbove = a.top < b.top;
            const Crate& above = firstAbove ? a : b;
            const Crate& below = firstAbove ? b : a;
            contacts.push_back({firstAbove ? first : second, firstAbove ? second : first,
                                above.top + above.size - below.top});
        }
    }
    return contacts;
}

float deepestOverlap(const std::vector<Crate>& crates, float floorY)
{
    float deepest = 0.f;
    for (const Contact& contact : findContacts(crates, floorY))
        deepest = std::max(deepest, contact.depth);
    return deepest;
}

float largestMove(const std::vector<Crate>& before, const std::vector<Crate>& after)
{
    float largest = 0.f;
    for (std::size_t index = 0; index < before.size() && index < after.size(); ++index)
        largest = std::max({largest, std::abs(after[index].left - before[index].left),
                            std::abs(after[index].top - before[index].top)});
    return largest;
}
