// Framework/TileMap.h (2025-26 course framework) - a level built from a small set of tiles,
// as the older framework's TileMap with references:
//
//     m_tileMap.loadTexture("gfx/tiles.png");
//     m_tileMap.setTileSet(tiles);                    // GameObjects: size, texture rectangle,
//                                                     // collider or not
//     m_tileMap.setTileMap(map, sf::Vector2u(10, 6)); // tile indices, row by row
//     m_tileMap.setPosition(sf::Vector2f(0, 400));
//     m_tileMap.buildLevel();
//     ...
//     for (GameObject& tile : m_tileMap.getLevel())   // collision against the placed tiles
//
// buildLevel's placing rule is placeTiles (../../CourseTileMap.h), shared with the older
// framework; the protected members keep this generation's m_ names, which lab code that
// derives from TileMap uses.
#pragma once

#include "../../CourseTileMap.h"
#include "Framework/GameObject.h"

#include <SFML/Graphics.hpp>
#include <string>
#include <vector>

class TileMap
{
public:
    // A file that does not load leaves the tiles untextured (SFML prints one line).
    void loadTexture(const std::string& filename);
    void setTileSet(const std::vector<GameObject>& tiles);
    // mapDimensions: columns and rows.
    void setTileMap(const std::vector<int>& tileIndices, sf::Vector2u mapDimensions);
    // Places the tiles; call it again after changing the set, the map or the position.
    void buildLevel();

    void render(sf::RenderWindow& window);
    // The placed tiles, to test for collisions (and change, e.g. collect a coin).
    std::vector<GameObject>& getLevel();
    void setPosition(sf::Vector2f topLeft);

protected:
    std::vector<GameObject> m_tileSet;
    std::vector<int> m_tileMap;      // tile indices, row by row
    std::vector<GameObject> m_level; // the placed tiles
    sf::Texture m_texture;
    sf::Vector2u m_mapSize; // columns and rows
    sf::Vector2f m_position;
};
