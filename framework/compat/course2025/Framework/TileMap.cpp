#include "Framework/TileMap.h"

void TileMap::loadTexture(const std::string& filename)
{
    if (!texture.loadFromFile(filename))
        return; // SFML has said which file; the tiles stay untextured
}

void TileMap::setTileSet(const std::vector<GameObject>& tiles)
{
    tileSet = tiles;
}

void TileMap::setTileMap(const std::vector<int>& tileIndices, sf::Vector2u mapDimensions)
{
    tileMap = tileIndices;
    mapSize = mapDimensions;
}

void TileMap::render(sf::RenderWindow& window)
{
    for (const GameObject& tile : level)
        window.draw(tile);
}

std::vector<GameObject>& TileMap::getLevel()
{
    return level;
}

void TileMap::setPosition(sf::Vector2f topLeft)
{
    position = topLeft;
}
