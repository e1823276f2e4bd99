// Framework/TileMap.h - the course's tile map: a level built from a small set of tiles.
//
//     tileMap.loadTexture("gfx/tiles.png");
//     tileMap.setTileSet(tiles);                   // GameObjects: size, texture rectangle,
//                                                  // collider or not
//     tileMap.setTileMap(map, sf::Vector2u(10, 6)); // tile indices, row by row
//     tileMap.setPosition(sf::Vector2f(0, 400));
//     tileMap.buildLevel();
//     ...
//     for (GameObject& tile : *tileMap.getLevel())  // collision against the placed tiles
//
// Every cell gets a copy of its tile, placed at the map's position plus (column, row) times
// the size of tile 0, and drawn with the map's texture. A cell whose index is not in the tile
// set (e.g. -1) is left empty.
#pragma once

#include "Framework/GameObject.h"

#include <SFML/Graphics.hpp>
#include <vector>

class TileMap
{
public:
    TileMap();
    ~TileMap();

    // A file that does not load leaves the tiles untextured (SFML prints one line).
    void loadTexture(const char* filename);
    void setTileSet(std::vector<GameObject> ts);
    // mapDimensions: columns and rows. Cells past the end of `tm` are left empty.
    void setTileMap(std::vector<int> tm, sf::Vector2u mapDimensions);
    // Places the tiles; call it again after changing the set, the map or the position.
    void buildLevel();

    void render(sf::RenderWindow* window);
    // The placed tiles, to test for collisions (and change, e.g. collect a coin).
    std::vector<GameObject>* getLevel();
    void setPosition(sf::Vector2f pos);

protected:
    std::vector<GameObject> tileSet;
    std::vector<int> tileMap;
    std::vector<GameObject> level;
    sf::Texture texture;
    sf::Vector2u mapSize;
    sf::Vector2f position;
};
