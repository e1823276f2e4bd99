// Framework/BaseLevel.h - the course's old level base class, kept so old lab code builds
// unchanged. SFML's graphics and Input come along, as they did in the old header.
//
// A course lab's Level derives from it, sets `window` and `input` (and, from week 10,
// `gameState` and `audio`) in its constructor, and is driven by the lab's own Main.cpp with
// a variable dt:
//     level.handleInput(dt); level.update(dt); level.render();
// New Hitbox programs derive from hitbox::Level instead (Level.h): a fixed step, a render
// that only reads state, and tests that need no window.
#pragma once

#include "Framework/Input.h"

#include <SFML/Graphics.hpp>
#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <string>

class AudioManager; // Framework/AudioManager.h
class GameState;    // Framework/GameState.h, or the lab's own copy

class BaseLevel
{
public:
    BaseLevel() = default;
    // The later weeks' form: the level is handed everything it may use.
    BaseLevel(sf::RenderWindow* hwnd, Input* in, GameState* gs = nullptr,
              AudioManager* aud = nullptr);
    virtual ~BaseLevel() = default;

    virtual void handleInput(float dt) = 0;
    virtual void update(float dt) = 0;
    virtual void render() = 0;

    // The colour beginDraw() clears the window to: the old framework's light blue.
    static const sf::Color backgroundColor;

protected:
    // Start a frame: clear the window. Then draw, then endDraw() shows the frame.
    // Both do nothing while `window` is null.
    void beginDraw();
    void endDraw();

    // Set by the derived level's constructor (Level(sf::RenderWindow* hwnd, Input* in)).
    sf::RenderWindow* window = nullptr;
    Input* input = nullptr;
    // Weeks 10 and 11: Main.cpp owns these and hands them to every level.
    GameState* gameState = nullptr;
    AudioManager* audio = nullptr;
};
