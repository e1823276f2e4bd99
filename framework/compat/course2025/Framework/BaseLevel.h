// Framework/BaseLevel.h (2025-26 course framework) - the base of a lab's Level, handed the
// window and the input by reference: Level level(window, input);
#pragma once

#include <SFML/Graphics.hpp>

#include "Framework/Input.h"

class BaseLevel
{
public:
    BaseLevel(sf::RenderWindow& window, Input& input);
    virtual ~BaseLevel() = default;

    virtual void handleInput(float dt) = 0;
    virtual void update(float dt) = 0;
    virtual void render() = 0;

protected:
    // Start a frame: clear the window to the course's light blue. Then draw, then endDraw()
    // shows the frame.
    void beginDraw();
    void endDraw();

    sf::RenderWindow& m_window;
    Input& m_input;
};
