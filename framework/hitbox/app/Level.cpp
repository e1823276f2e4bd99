#include "hitbox/app/Level.h"

namespace hitbox
{

void Level::handleInput(const Input&, float) {}

void Level::renderDebug(DebugRenderer&) const {}

sf::Vector2f Level::getWorldSize() const
{
    return defaultWorldSize;
}

std::string Level::getHelpText() const
{
    return {};
}

std::string Level::describeState() const
{
    return {};
}

bool Level::handleEscape()
{
    return false;
}

} // namespace hitbox
