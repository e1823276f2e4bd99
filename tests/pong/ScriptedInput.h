// ScriptedInput.h - two players' keys and a wandering mouse from a seeded generator: input no
// test author would line up by hand (PongReplayTests.cpp, RecordMatch.cpp).
#pragma once

#include "hitbox/app/Input.h"

#include <random>

namespace pongtesting
{

// Each of W, S, Up and Down goes down or up at random now and then (1 step in 16 each); the
// mouse moves by up to 3 pixels on each axis.
inline void scriptInput(hitbox::Input& input, std::mt19937& random)
{
    const sf::Keyboard::Key keys[] = {sf::Keyboard::Key::W, sf::Keyboard::Key::S,
                                      sf::Keyboard::Key::Up, sf::Keyboard::Key::Down};
    std::uniform_int_distribution<int> pick(0, 15);
    for (sf::Keyboard::Key key : keys)
    {
        const int roll = pick(random);
        if (roll == 0)
            input.setKeyDown(key);
        else if (roll == 1)
            input.setKeyUp(key);
    }
    std::uniform_real_distribution<float> move(-3.f, 3.f);
    input.setMousePosition(input.getMousePosition() + sf::Vector2f(move(random), move(random)));
}

} // namespace pongtesting
