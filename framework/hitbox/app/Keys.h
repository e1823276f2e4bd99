// Keys.h - the keys every Hitbox program shares, and the help text that names them.
//
// The window acts on them (private/Window.cpp), the help line shows them, and a level that
// asks "did a player press something?" leaves them out with isSharedKey(). To change a key,
// change its row here.
#pragma once

#include <SFML/Window/Keyboard.hpp>

#include <array>
#include <string>

namespace hitbox
{

// The number of key codes: sf::Keyboard::Key values run from 0 to keyCount - 1.
constexpr int keyCount = static_cast<int>(sf::Keyboard::KeyCount);

enum class SharedAction
{
    ToggleDebug, // debug boxes on/off
    Pause,       // pause / resume
    Step,        // one simulation step while paused
    Screenshot,  // save the window to screenshot-<date>-<time>.png
    Quit         // quit, or back to the menu where a level has one
};

struct SharedKey
{
    sf::Keyboard::Key key;
    SharedAction action;
    const char* help; // how the help line names it
};

constexpr std::array<SharedKey, 5> sharedKeys{{
    {sf::Keyboard::Key::F1, SharedAction::ToggleDebug, "F1 debug boxes"},
    {sf::Keyboard::Key::P, SharedAction::Pause, "P pause"},
    {sf::Keyboard::Key::N, SharedAction::Step, "N step"},
    {sf::Keyboard::Key::F12, SharedAction::Screenshot, "F12 screenshot"},
    {sf::Keyboard::Key::Escape, SharedAction::Quit, "Esc quit"},
}};

// The shared key row for `key` (an sf::Keyboard::Key code), or nullptr if it is not one.
[[nodiscard]] const SharedKey* findSharedKey(int key);

// True when `key` is one of the shared keys above.
[[nodiscard]] bool isSharedKey(int key);

// "F1 debug boxes   P pause   ...": the start of every window's help line.
[[nodiscard]] std::string sharedKeysHelp();

} // namespace hitbox
