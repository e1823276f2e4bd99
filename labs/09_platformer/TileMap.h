// TileMap.h - a platformer level made of square tiles, read from a text file.
//
// The file is a picture of the level, one character per tile (seed 001's tile level):
//     #  solid tile        .  empty        P  where the player starts (an empty tile)
// Every row must have the same number of tiles. A mistake in the file stops the program with
// ONE line naming the file, the line and what is wrong, so a student can fix it at once.
#pragma once

#include "hitbox/app/Assets.h"
#include "hitbox/geometry/Shapes.h"

#include <string>
#include <vector>

// A level file that cannot be read as a level. An AssetError, so hitbox::run prints the
// message and exits with code 1 like any other broken asset.
class LevelFileError : public hitbox::AssetError
{
public:
    using hitbox::AssetError::AssetError;
};

// A rectangle of tiles, first..last inclusive on both axes. Empty when last < first.
struct TileRegion
{
    int firstColumn = 0;
    int lastColumn = -1;
    int firstRow = 0;
    int lastRow = -1;

    bool isEmpty() const { return lastColumn < firstColumn || lastRow < firstRow; }
    int tileCount() const
    {
        return isEmpty() ? 0 : (lastColumn - firstColumn + 1) * (lastRow - firstRow + 1);
    }
};

class TileMap
{
public:
    static constexpr float tileSize = 48.f; // pixels, the same on both axes

    // Reads a level from text. `sourceName` (usually the file's path) starts every error
    // message. Throws LevelFileError.
    static TileMap parse(const std::string& text, const std::string& sourceName);
    // Reads "assets/<relativePath>", e.g. "levels/platformer.txt". Throws hitbox::AssetError
    // (missing file: names the path and the fix) or LevelFileError (bad contents).
    static TileMap load(const std::string& relativePath);

    int getColumns() const { return columns; }
    int getRows() const { return rows; }
    hitbox::Vec2 getSizeInPixels() const;
    // The top-left corner of the 'P' tile, in pixels.
    hitbox::Vec2 getPlayerStart() const { return playerStart; }

    // Outside the map there is nothing: a player who leaves it falls out of the world.
    bool isSolid(int column, int row) const;
    hitbox::Box tileBox(int column, int row) const;

    // The tiles a box covers. Only tiles it SHARES AREA with count (the edge rule): a box
    // whose right edge lies exactly on a tile boundary does not reach into the next column.
    // The result is clipped to the map.
    TileRegion tilesUnder(const hitbox::Box& box) const;

private:
    int columns = 0;
    int rows = 0;
    std::vector<std::string> tiles; // tiles[row][column], only '#' and '.'
    hitbox::Vec2 playerStart;
};
