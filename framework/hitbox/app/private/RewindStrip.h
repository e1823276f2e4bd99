// RewindStrip.h - the paused window's rewind strip: where it lies, how it is drawn, and how
// Left/Right and a click on it choose the step shown (Rewind.h does the stepping).
#pragma once

#include "hitbox/app/Rewind.h"
#include "hitbox/app/Timeline.h"
#include "hitbox/geometry/Shapes.h"

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/System/Vector2.hpp>
#include <SFML/Window/Keyboard.hpp>

namespace hitbox
{

// What the paused window can rewind (null: nothing) and the events its strip shows.
struct RewindTools
{
    RewindLevel* rewind = nullptr;
    const Timeline* timeline = nullptr;
};

// Where the strip lies in a world of size `world`: along the bottom, just above the help line.
[[nodiscard]] Box stripArea(sf::Vector2f world);
// True when the strip is shown: paused, with a level that can be rewound.
[[nodiscard]] bool canRewind(const RewindTools& tools, bool paused);
// The kept steps, the enters and exits among them (Stay events are left out), the step shown.
void drawRewindStrip(sf::RenderTarget& target, sf::Vector2f world, const RewindTools& tools);
// The step Left (one back) and Right (one forward) ask for from step `from`; other keys: `from`.
// The window shows what a frame's presses asked for once, after them (a level rebuilt to show
// a step, RewindReplay.h, is then re-simulated once a frame, not once a key repeat).
[[nodiscard]] long long stepForKey(long long from, sf::Keyboard::Key key);
// The step under world point `at` on the strip; -1 when `at` is off the strip.
[[nodiscard]] long long stepForClick(const RewindLevel& rewind, sf::Vector2f world,
                                     sf::Vector2f at);

} // namespace hitbox
