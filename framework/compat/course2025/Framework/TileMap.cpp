#include "Framework/TileMap.h"

void TileMap::loadTexture(const std::string& filename)
{
    if (!m_texture.loadFromFile(filename))
        return; // SFML has said which file; the tiles stay untextured
}

void TileMap::setTileSet(const std::vector<GameObject>& tileSet)
{
    m_tileSet = tileSet;
}

void TileMap::setTileMap(const std::vector<int>& tileMap, sf::Vector2u mapDimensions)
{
    m_tileMap = tileMap;
    m_mapSize = mapDimensions;
}

void TileMap::buildLevel()
{
    m_level.clear();
    if (m_tileSet.empty())
        return;
    const sf::Vector2f tileSize = m_tileSet[0].getSize();
    for (unsigned row = 0; row < m_mapSize.y; ++row)
    {
        for (unsigned column = 0; column < m_mapSize.x; ++column)
        {
            const std::size_t cell = std::size_t{row} * m_mapSize.x + column;
            if (cell >= m_tileMap.size())
                return;
            const int tileIndex = m_tileMap[cell];
            if (tileIndex < 0 || tileIndex >= static_cast<int>(m_tileSet.size()))
                continue;
            GameObject tile = m_tileSet[static_cast<std::size_t>(tileIndex)];
            tile.setPosition({m_position.x + static_cast<float>(column) * tileSize.x,
                              m_position.y + static_cast<float>(row) * tileSize.y});
            tile.setTexture(&m_texture);
            m_level.push_back(tile);
        }
    }
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

void TileMap::setPosition(sf::Vector2f position)
{
    m_position = position;
}
