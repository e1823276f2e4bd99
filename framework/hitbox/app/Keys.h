// Keys.h - the keys every Hitbox program shares, and the help text that names them.
//
// The window acts on them (private/Window.cpp), the help line shows them, and a level that
// asks "did a player press something?" leaves them out with isSharedKey(). To change a key,
// change its row here: the help line names the key from the row's key itself (keyName).
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
    const char* does; // what the help line says it does, after the key's name
};

constexpr std::array<SharedKey, 5> sharedKeys{{
    {sf::Keyboard::Key::F1, SharedAction::ToggleDebug, "debug boxes"},
    {sf::Keyboard::Key::P, SharedAction::Pause, "pause"},
    {sf::Keyboard::Key::N, SharedAction::Step, "step"},
    {sf::Keyboard::Key::F12, SharedAction::Screenshot, "screenshot"},
    {sf::Keyboard::Key::Escape, SharedAction::Quit, "quit"},
}};

// How the help line names a key: "A" to "Z", "F1" to "F15", "Esc"; any other key "key N" (its
// code). Worked out from the code (A..Z and F1..F15 are consecutive in SFML 2 and 3), not with
// sf::Keyboard::getDescription, which SFML 2.5 lacks and which follows the keyboard layout.
[[nodiscard]] std::string keyName(sf::Keyboard::Key key);

// The shared key row for `key` (an sf::Keyboard::Key code), or nullptr if it is not one.
[[nodiscard]] const SharedKey* findSharedKey(int key);

// True when `key` is one of the shared keys above.
[[nodiscard]] bool isSharedKey(int key);

// "F1 debug boxes   P pause   ...": the start of every window's help line.
[[nodiscard]] std::string sharedKeysHelp();

} // namespace hitbox
