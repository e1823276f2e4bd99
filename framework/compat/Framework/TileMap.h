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
// The data and buildLevel's placing rule are CourseTileMap's (../CourseTileMap.h), shared
// with the 2025-26 framework; this class adds the older framework's signatures. Its protected
// members, as the course had them: tileSet, tileMap, level, texture, mapSize, position.
#pragma once

#include "../CourseTileMap.h"
#include "Framework/GameObject.h"

#include <SFML/Graphics.hpp>
#include <vector>

class TileMap : public CourseTileMap<GameObject>
{
public:
    TileMap();
    ~TileMap();

    // A file that does not load leaves the tiles untextured (SFML prints one line).
    void loadTexture(const char* filename);
    void setTileSet(std::vector<GameObject> ts);
    // mapDimensions: columns and rows. Cells past the end of `tm` are left empty.
    void setTileMap(std::vector<int> tm, sf::Vector2u mapDimensions);

    void render(sf::RenderWindow* window);
    // The placed tiles, to test for collisions (and change, e.g. collect a coin).
    std::vector<GameObject>* getLevel();
    void setPosition(sf::Vector2f pos);
};
