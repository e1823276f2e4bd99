// Platforms.h - the two kinds of ground that are not square blocks: one-way platforms
// (task 5) and slopes (task 6). Each is one function of plain values; PlatformerLevel calls
// them every step for the tiles near the player.
#pragma once

#include "hitbox/geometry/OneWayPlatform.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Slope.h"

// Task 5: does a one-way platform stop the player's move this step? RULE: only a player
// moving down (move.y > 0) whose bottom was at or above the platform's top when the step
// began (touching counts as above: standing on it holds) and would end strictly below it,
// and who shares some width with the platform when its bottom reaches the top. Then `move.y`
// is cut so the bottom ends exactly on the top; otherwise the move is returned unchanged.
// (The framework's hitbox::oneWayPlatformStop, OneWayPlatform.h, follows the same rule.)
[[nodiscard]] hitbox::OneWayStop landOnOneWay(const hitbox::Box& player, hitbox::Vec2 move,
                                              const hitbox::Box& platform);

// Task 6: the player's foot (the middle of its bottom) on a slope. RULE: when the player is
// not rising (velocityY >= 0) and the foot is over the slope, a foot below the surface (but
// no deeper than the slope's lower end) is pushed up onto it, and one above it by at most
// `snapDistance` (>= 0; 0: never pulled down) is pulled down onto it; either way the player
// is grounded. A rising player (a jump) is never moved. (The same rule as the framework's
// hitbox::standOnSlope, Slope.h; the surface's height comes from the given hitbox::slopeGroundAt.)
[[nodiscard]] hitbox::SlopeFoot footOnSlope(const hitbox::Box& player, float velocityY,
                                            const hitbox::Slope& slope, float snapDistance);
