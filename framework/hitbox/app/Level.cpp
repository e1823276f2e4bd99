#include "hitbox/app/Level.h"

namespace hitbox
{

void Level::handleInput(const Input&, float) {}

void Level::renderBlended(sf::RenderTarget& target, float) const
{
    render(target);
}

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

std::vector<PairEvent> Level::getContactEvents() const
{
    return {};
}

std::unique_ptr<LevelState> Level::saveState() const
{
    return nullptr;
}

void Level::restoreState(const LevelState&) {}

bool Level::handleEscape()
{
    return false;
}

} // namespace hitbox
