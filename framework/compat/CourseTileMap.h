// CourseTileMap.h - what both generations' TileMap share (Framework/TileMap.h for 2019-24,
// course2025/Framework/TileMap.h for 2025-26): the tile set, the map, the placed tiles and the
// one rule for placing them. Each generation's TileMap derives from it and adds only its own
// signatures (pointers and by-value vectors in the older one, references in the newer).
//
// A template on the tile type because each generation has its own GameObject (a program only
// ever has one of them). The members keep the older framework's names (`tileSet`, `level`,
// ...), which its header made protected for lab code that derives from TileMap.
#pragma once

#include <SFML/Graphics.hpp>

#include <cstddef>
#include <vector>

// The placing rule of buildLevel: every cell gets a copy of its tile, placed at `position`
// plus (column, row) times the size of tile 0, drawn with `texture`. A cell whose index is
// not in the tile set (e.g. -1) is left empty; cells past the end of `tileMap` too.
// `mapSize`: columns and rows.
template <typename Tile>
std::vector<Tile> placeTiles(const std::vector<Tile>& tileSet, const std::vector<int>& tileMap,
                             sf::Vector2u mapSize, sf::Vector2f position,
                             const sf::Texture* texture)
{
    std::vector<Tile> placed;
    if (tileSet.empty())
        return placed;
    const sf::Vector2f tileSize = tileSet[0].getSize();
    const std::size_t cells = std::size_t{mapSize.x} * mapSize.y;
    for (std::size_t cell = 0; cell < cells && cell < tileMap.size(); ++cell)
    {
        const int tileIndex = tileMap[cell];
        if (tileIndex < 0 || tileIndex >= static_cast<int>(tileSet.size()))
            continue;
        const float column = static_cast<float>(cell % mapSize.x);
        const float row = static_cast<float>(cell / mapSize.x);
        placed.push_back(tileSet[static_cast<std::size_t>(tileIndex)]);
        placed.back().setPosition(
            {position.x + column * tileSize.x, position.y + row * tileSize.y});
        placed.back().setTexture(texture);
    }
    return placed;
}

template <typename Tile>
class CourseTileMap
{
public:
    // Places the tiles (placeTiles above). Call it again after changing the set, the map or
    // the position.
    void buildLevel() { level = placeTiles(tileSet, tileMap, mapSize, position, &texture); }

protected:
    std::vector<Tile> tileSet;
    std::vector<int> tileMap; // tile indices, row by row
    std::vector<Tile> level;  // the placed tiles
    sf::Texture texture;
    sf::Vector2u mapSize; // columns and rows
    sf::Vector2f position;
};
