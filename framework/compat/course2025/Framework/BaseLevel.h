// Framework/BaseLevel.h (2025-26 course framework) - the base of a lab's Level, handed the
// window, the input and (from the week on game states) the game state by reference:
//     Level level(window, input);             // weeks 1-4
//     Level level(window, input, gameState);  // later weeks: Menu, Level, Pause share it
// GameState.h is the lab's own when it has one (its enum of states may be edited).
#pragma once

#include <SFML/Graphics.hpp>

#include "Framework/GameState.h"
#include "Framework/Input.h"

class BaseLevel
{
public:
    // Without a game state, m_gameState is one of the level's own, seen by no other level.
    BaseLevel(sf::RenderWindow& window, Input& input);
    BaseLevel(sf::RenderWindow& window, Input& input, GameState& gameState);
    virtual ~BaseLevel() = default;
    // Not copyable: a copy's m_gameState would still be the original's own game state.
    BaseLevel(const BaseLevel&) = delete;
    BaseLevel& operator=(const BaseLevel&) = delete;

    virtual void handleInput(float dt) = 0;
    virtual void update(float dt) = 0;
    virtual void render() = 0;

protected:
    // Start a frame: clear the window to the course's light blue. Then draw, then endDraw()
    // shows the frame.
    void beginDraw();
    void endDraw();

private:
    GameState m_ownGameState; // declared before m_gameState, which may refer to it

protected:
    sf::RenderWindow& m_window;
    Input& m_input;
    GameState& m_gameState;
};
