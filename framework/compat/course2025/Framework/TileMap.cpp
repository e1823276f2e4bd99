#include "Framework/TileMap.h"

void TileMap::loadTexture(const std::string& filename)
{
    if (!m_texture.loadFromFile(filename))
        return; // SFML has said which file; the tiles stay untextured
}

void TileMap::setTileSet(const std::vector<GameObject>& tiles)
{
    m_tileSet = tiles;
}

void TileMap::setTileMap(const std::vector<int>& tileIndices, sf::Vector2u mapDimensions)
{
    m_tileMap = tileIndices;
    m_mapSize = mapDimensions;
}

void TileMap::buildLevel()
{
    m_level = placeTiles(m_tileSet, m_tileMap, m_mapSize, m_position, &m_texture);
}

void TileMap::render(sf::RenderWindow& window)
{
    for (const GameObject& tile : m_level)
        window.draw(tile);
}

std::vector<GameObject>& TileMap::getLevel()
{
    return m_level;
}

void TileMap::setPosition(sf::Vector2f topLeft)
{
    m_position = topLeft;
}
