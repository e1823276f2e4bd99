#include "Framework/TileMap.h"

#include <utility>

TileMap::TileMap() = default;

TileMap::~TileMap() = default;

void TileMap::loadTexture(const char* filename)
{
    texture.loadFromFile(filename); // SFML says which file did not load
}

void TileMap::setTileSet(std::vector<GameObject> ts)
{
    tileSet = std::move(ts);
}

void TileMap::setTileMap(std::vector<int> tm, sf::Vector2u mapDimensions)
{
    tileMap = std::move(tm);
    mapSize = mapDimensions;
}

void TileMap::render(sf::RenderWindow* window)
{
    for (const GameObject& tile : level)
        window->draw(tile);
}

std::vector<GameObject>* TileMap::getLevel()
{
    return &level;
}

void TileMap::setPosition(sf::Vector2f pos)
{
    position = pos;
}
