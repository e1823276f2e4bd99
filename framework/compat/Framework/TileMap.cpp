#include "Framework/TileMap.h"

TileMap::TileMap() = default;

TileMap::~TileMap() = default;

void TileMap::loadTexture(const char* filename)
{
    texture.loadFromFile(filename);
}

void TileMap::setTileSet(std::vector<GameObject> ts)
{
    tileSet = ts;
}

void TileMap::setTileMap(std::vector<int> tm, sf::Vector2u mapDimensions)
{
    tileMap = tm;
    mapSize = mapDimensions;
}

void TileMap::buildLevel()
{
    level.clear();
    if (tileSet.empty())
        return;
    const sf::Vector2f tileSize = tileSet[0].getSize();
    for (unsigned row = 0; row < mapSize.y; ++row)
    {
        for (unsigned column = 0; column < mapSize.x; ++column)
        {
            const std::size_t cell = row * mapSize.x + column;
            if (cell >= tileMap.size())
                return;
            const int tileIndex = tileMap[cell];
            if (tileIndex < 0 || tileIndex >= static_cast<int>(tileSet.size()))
                continue;
            GameObject tile = tileSet[tileIndex];
            tile.setPosition(position.x + column * tileSize.x, position.y + row * tileSize.y);
            tile.setTexture(&texture);
            level.push_back(tile);
        }
    }
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
