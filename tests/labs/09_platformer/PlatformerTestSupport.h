// PlatformerTestSupport.h - a scripted player for lab 9's grading tests: small maps written
// as text, keys held and pressed, and fixed steps with no window.
#pragma once

#include "PlatformerLevel.h"
#include "TileMap.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"

#include <string>

namespace platformertest
{
// A closed room 10 tiles wide and 10 high; the floor's top is at y = 432.
inline const char* const room = "##########\n"
                                "#........#\n"
                                "#........#\n"
                                "#........#\n"
                                "#........#\n"
                                "#........#\n"
                                "#........#\n"
                                "#...P....#\n"
                                "#........#\n"
                                "##########\n";
constexpr float roomFloorTop = 9 * TileMap::tileSize;

// The same room with a ledge on the left: its top is y = 240, its right edge x = 240.
inline const char* const roomWithLedge = "##########\n"
                                         "#........#\n"
                                         "#........#\n"
                                         "#........#\n"
                                         "#........#\n"
                                         "#####....#\n"
                                         "#........#\n"
                                         "#...P....#\n"
                                         "#........#\n"
                                         "##########\n";
constexpr float ledgeTop = 5 * TileMap::tileSize;
constexpr float ledgeRight = 5 * TileMap::tileSize;

// A shaft `rows` tiles deep with a floor ONE tile thick at the bottom and nothing below it:
// whoever gets through the floor falls out of the world.
inline std::string deepShaft(int rows)
{
    std::string text = "#.P.#\n";
    for (int row = 1; row < rows - 1; ++row)
        text += "#...#\n";
    text += "#####\n";
    return text;
}

struct Game
{
    // Every tile of the map is tested, as in the starter: one mistake in task 3 (the tiles
    // under the player) costs task 3 alone. Task 3's own tests switch it back off.
    explicit Game(const std::string& mapText) : level(TileMap::parse(mapText, "test map"))
    {
        level.setWholeMapSearch(true);
    }

    // One frame of `dt` seconds, as hitbox::App runs it: input, update, end of frame.
    void frame(float dt = hitbox::stepSeconds)
    {
        level.handleInput(input, dt);
        level.update(dt);
        input.update();
    }
    void run(float seconds, float dt = hitbox::stepSeconds)
    {
        const int frames = static_cast<int>(seconds / dt + 0.5f);
        for (int index = 0; index < frames; ++index)
            frame(dt);
    }
    // Fall straight down at `speed` pixels per second for `seconds`, whatever task 1's
    // gravity and task 4's speed cap do: the velocity is set before every frame. (Gravity
    // adds one step's worth on top, still under the cap.) Landing stops the fall as a floor
    // stops gravity, so the player stands on it.
    void fall(float seconds, float speed = fallSpeed)
    {
        const int frames = static_cast<int>(seconds / hitbox::stepSeconds + 0.5f);
        for (int index = 0; index < frames; ++index)
        {
            level.setPlayerVelocity({velocity().x, speed});
            frame();
        }
    }
    // fall(), stopping after the step that lands (grounded); true when it landed. What
    // happens once the player stands (task 1's jump, gravity) is left out of the test.
    bool fallUntilLanded(float seconds, float speed = fallSpeed)
    {
        const int frames = static_cast<int>(seconds / hitbox::stepSeconds + 0.5f);
        for (int index = 0; index < frames; ++index)
        {
            level.setPlayerVelocity({velocity().x, speed});
            frame();
            if (level.isGrounded())
                return true;
        }
        return false;
    }
    // 15 pixels a step: under a tile, and under the speed cap with one step of gravity.
    static constexpr float fallSpeed = 1800.f;
    // Press a key for exactly one frame.
    void tap(sf::Keyboard::Key key, float dt = hitbox::stepSeconds)
    {
        input.setKeyDown(key);
        frame(dt);
        input.setKeyUp(key);
    }
    hitbox::Vec2 position() const { return level.getPlayer().getPosition(); }
    hitbox::Vec2 velocity() const { return level.getPlayer().getVelocity(); }
    float feet() const { return position().y + Player::height; }

    PlatformerLevel level;
    hitbox::Input input;
};
} // namespace platformertest
