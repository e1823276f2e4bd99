// TileMap.h - a platformer level made of square tiles, read from a text file.
//
// The file is a picture of the level, one character per tile:
//     #  solid tile        .  empty        P  where the player starts (an empty tile)
//     -  one-way platform (solid only from above, at the tile's top; task 5)
//     /  slope rising to the right    \  slope falling to the right (task 6)
//     C  checkpoint: a trigger zone the player passes through (task 7)
// Every row must have the same number of tiles, and a level may be at most maxTilesAcross
// tiles wide and tall, inside the range the collision maths is exact for. A mistake in the file
// stops the program with ONE line naming the file, the line and what is wrong, so a student can fix
// it at once.
#pragma once

#include "hitbox/app/Assets.h"
#include "hitbox/geometry/Shapes.h"

#include <string>
#include <vector>

// A level file that cannot be read as a level. An AssetError; lab 9's main() turns it (and
// a missing --level file) into bad input, so hitbox::run prints it and exits with code 2.
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

// What a tile is. Only Solid tiles are tested with the collision points; the others have
// their own rules (PlatformerLevel.cpp).
enum class Tile
{
    Empty,
    Solid,
    OneWay,    // '-'
    SlopeUp,   // '/': from the tile's bottom-left corner up to its top-right corner
    SlopeDown, // '\': from the top-left corner down to the bottom-right corner
    Checkpoint // 'C'
};

class TileMap
{
public:
    static constexpr float tileSize = 48.f; // pixels, the same on both axes

    // A level file may be at most this big (1 MiB: a 1000 x 1000 tile level fits).
    static constexpr long long maxFileBytes = 1 << 20;

    // The most tiles a level may have across or down: 20000 tiles are 960000 px, inside
    // hitbox::exactRange (1e6 px, geometry/Range.h) with room for a player who falls out of
    // the bottom. Beyond it floats round a step's movement away (at 2.5e7 px a float's step
    // is 2 px), so a wider level is refused when it is read, never run wrong.
    static constexpr int maxTilesAcross = 20000;

    // Reads a level from text. `sourceName` (usually the file's path) starts every error
    // message. Lines end in \n or \r\n; a UTF-8 byte-order mark at the start is skipped.
    // A byte that is not a tile is named escaped (\r, \0, \xEF), never printed raw.
    // Throws LevelFileError.
    static TileMap parse(const std::string& text, const std::string& sourceName);
    // Reads a level file: a relative path such as "levels/platformer.txt" is looked up in
    // assets/, an absolute path is used as it is. Only a regular file of at most maxFileBytes
    // is read. Throws std::invalid_argument for "" (a usage mistake), hitbox::AssetError
    // (missing: names the path and the fix) or LevelFileError (a folder, a device or a pipe,
    // unreadable, too big, or bad contents), each with one line saying which.
    static TileMap load(const std::string& path);

    int getColumns() const { return columns; }
    int getRows() const { return rows; }
    hitbox::Vec2 getSizeInPixels() const;
    // The top-left corner of the 'P' tile, in pixels.
    hitbox::Vec2 getPlayerStart() const { return playerStart; }

    // Outside the map there is nothing: a player who leaves it falls out of the world.
    bool isSolid(int column, int row) const;
    // The kind of a tile; Empty outside the map.
    Tile tileAt(int column, int row) const;
    hitbox::Box tileBox(int column, int row) const;

    // The tiles a box covers. Only tiles it SHARES AREA with count (the edge rule): a box
    // whose right edge lies exactly on a tile boundary does not reach into the next column.
    // The result is clipped to the map.
    TileRegion tilesUnder(const hitbox::Box& box) const;

private:
    int columns = 0;
    int rows = 0;
    std::vector<std::string> tiles; // tiles[row][column]: '#', '.', '-', '/', '\\' or 'C'
    hitbox::Vec2 playerStart;
};
