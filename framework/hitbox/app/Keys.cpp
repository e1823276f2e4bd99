#include "hitbox/app/Keys.h"

namespace hitbox
{

const SharedKey* findSharedKey(int key)
{
    for (const SharedKey& shared : sharedKeys)
        if (static_cast<int>(shared.key) == key)
            return &shared;
    return nullptr;
}

bool isSharedKey(int key)
{
    return findSharedKey(key) != nullptr;
}

std::string keyName(sf::Keyboard::Key key)
{
    const int code = static_cast<int>(key);
    const int a = static_cast<int>(sf::Keyboard::Key::A);
    const int f1 = static_cast<int>(sf::Keyboard::Key::F1);
    if (code >= a && code <= static_cast<int>(sf::Keyboard::Key::Z))
        return std::string(1, static_cast<char>('A' + (code - a)));
    if (code >= f1 && code <= static_cast<int>(sf::Keyboard::Key::F15))
        return "F" + std::to_string(code - f1 + 1);
    if (key == sf::Keyboard::Key::Escape)
        return "Esc";
    return "key " + std::to_string(code);
}

std::string sharedKeysHelp()
{
    std::string help;
    for (const SharedKey& shared : sharedKeys)
        help += (help.empty() ? "" : "   ") + keyName(shared.key) + " " + shared.does;
    return help;
}

} // namespace hitbox
