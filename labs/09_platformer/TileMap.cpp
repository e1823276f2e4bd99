#include "TileMap.h"

#include "hitbox/app/Options.h"
#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/Shapes.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace
{
// "levels/x.txt line 4: ..." - every complaint about a file starts the same way.
LevelFileError errorAt(const std::string& source, int line, const std::string& what)
{
    return LevelFileError("level file '" + hitbox::printable(source, 200) + "' line " +
                          std::to_string(line) + ": " + what);
}

LevelFileError fileError(const std::string& path, const std::string& what)
{
    return LevelFileError("level file '" + hitbox::printable(path, 200) + "' " + what);
}

// Why a tile character is wrong, with the fix for the usual cause.
std::string unknownTile(char tile, std::size_t column)
{
    std::string what = "unknown tile '" + hitbox::printable(std::string(1, tile)) + "' in column " +
                       std::to_string(column + 1);
    if (tile == '\r')
        return what + " (a line ends in a lone carriage return: save the file with Unix or "
                      "Windows line ends)";
    return what + " (use # for solid, . for empty, - for a one-way platform, / and \\ for "
                  "slopes, C for a checkpoint, P for the player start)";
}
// A level too large for exact collision maths (TileMap::maxTilesAcross).
std::string tooBig(const std::string& direction)
{
    return "the level is over " + std::to_string(TileMap::maxTilesAcross) + " tiles " + direction +
           "; the collision maths is exact to " +
           std::to_string(static_cast<long long>(hitbox::exactRange)) +
           " px (hitbox/geometry/Range.h), so a level may be at most " +
           std::to_string(TileMap::maxTilesAcross) + " tiles wide and tall";
}
} // namespace

TileMap TileMap::parse(const std::string& text, const std::string& sourceName)
{
    TileMap map;
    // Windows Notepad may start a UTF-8 file with a byte-order mark: it is not a tile.
    const std::string byteOrderMark = "\xEF\xBB\xBF";
    const bool hasMark = text.compare(0, byteOrderMark.size(), byteOrderMark) == 0;
    std::istringstream stream(hasMark ? text.substr(byteOrderMark.size()) : text);
    std::string line;
    int lineNumber = 0;
    int startLine = 0;
    while (std::getline(stream, line))
    {
        ++lineNumber;
        // A file saved on Windows ends its lines with "\r\n": the '\r' is not a tile.
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.empty())
            continue; // blank lines (usually at the end of the file) are not rows

        if (map.tiles.empty())
        {
            if (line.size() > static_cast<std::size_t>(maxTilesAcross))
                throw errorAt(sourceName, lineNumber, tooBig("wide"));
            map.columns = static_cast<int>(line.size());
        }
        else if (static_cast<int>(line.size()) != map.columns)
            throw errorAt(sourceName, lineNumber,
                          "this row has " + std::to_string(line.size()) +
                              " tiles but the first row has " + std::to_string(map.columns) +
                              " (every row must be the same length)");

        // [slide:tile-level-parse]
        for (std::size_t column = 0; column < line.size(); ++column)
        {
            const char tile = line[column];
            if (tile == 'P')
            {
                if (startLine != 0)
                    throw errorAt(sourceName, lineNumber,
                                  "a second player start 'P' (the first is on line " +
                                      std::to_string(startLine) + "; keep one)");
                startLine = lineNumber;
                map.playerStart = {static_cast<float>(column) * tileSize,
                                   static_cast<float>(map.tiles.size()) * tileSize};
                line[column] = '.'; // the start is an empty tile
            }
            else if (std::string("#.-/\\C").find(tile) == std::string::npos)
                throw errorAt(sourceName, lineNumber, unknownTile(tile, column));
        }
        map.tiles.push_back(line);
        // [/slide]
        if (map.tiles.size() > static_cast<std::size_t>(maxTilesAcross))
            throw errorAt(sourceName, lineNumber, tooBig("tall"));
    }

    if (map.tiles.empty())
        throw fileError(sourceName, "has no rows (draw the level with # . and one P)");
    if (startLine == 0)
        throw errorAt(sourceName, lineNumber,
                      "reached the end of the file without a player start (put one 'P' on an "
                      "empty tile)");
    map.rows = static_cast<int>(map.tiles.size());
    return map;
}

TileMap TileMap::load(const std::string& path)
{
    namespace fs = std::filesystem;
    if (path.empty())
        throw std::invalid_argument("--level needs a file name, e.g. levels/platformer.txt");
    std::string found = path;
    if (!fs::path(path).is_absolute())
    {
        try
        {
            found = hitbox::findAsset(path);
        }
        catch (const hitbox::AssetError& error)
        {
            throw hitbox::AssetError(std::string(error.what()) +
                                     " Levels are text files in assets/levels/; pick one with "
                                     "--level levels/NAME.txt.");
        }
    }
    // Look before opening: opening a pipe would wait forever, and a device never ends.
    std::error_code error;
    const fs::file_status status = fs::status(found, error);
    if (!fs::exists(status))
        throw fileError(found, "does not exist");
    if (fs::is_directory(status))
        throw fileError(found, "is a folder; pick a file in it, e.g. levels/platformer.txt");
    if (!fs::is_regular_file(status))
        throw fileError(found,
                        "is not a regular file (a device or a pipe); a level is a text file");
    const auto size = fs::file_size(found, error);
    if (!error && size > static_cast<std::uintmax_t>(maxFileBytes))
        throw fileError(found, "is " + std::to_string(size) +
                                   " bytes; a level file may be at most " +
                                   std::to_string(maxFileBytes) + " bytes (1 MiB)");

    std::ifstream file(found, std::ios::binary);
    if (!file)
        throw fileError(found, "cannot be read: " + std::generic_category().message(errno));
    // Read one byte past the limit: a file that grew since it was measured is still caught.
    std::string text(static_cast<std::size_t>(maxFileBytes) + 1, '\0');
    file.read(&text[0], static_cast<std::streamsize>(text.size()));
    if (file.bad())
        throw fileError(found, "cannot be read (an error while reading)");
    text.resize(static_cast<std::size_t>(file.gcount()));
    if (text.size() > static_cast<std::size_t>(maxFileBytes))
        throw fileError(found, "is over " + std::to_string(maxFileBytes) +
                                   " bytes; a level file may be at most that (1 MiB)");
    return parse(text, found);
}

hitbox::Vec2 TileMap::getSizeInPixels() const
{
    return {static_cast<float>(columns) * tileSize, static_cast<float>(rows) * tileSize};
}

// [slide:tile-lookup]
bool TileMap::isSolid(int column, int row) const
{
    if (column < 0 || row < 0 || column >= columns || row >= rows)
        return false;
    return tiles[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] == '#';
}
// [/slide]

Tile TileMap::tileAt(int column, int row) const
{
    if (column < 0 || row < 0 || column >= columns || row >= rows)
        return Tile::Empty;
    switch (tiles[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)])
    {
    case '#':
        return Tile::Solid;
    case '-':
        return Tile::OneWay;
    case '/':
        return Tile::SlopeUp;
    case '\\':
        return Tile::SlopeDown;
    case 'C':
        return Tile::Checkpoint;
    default:
        return Tile::Empty;
    }
}

hitbox::Box TileMap::tileBox(int column, int row) const
{
    return {static_cast<float>(column) * tileSize, static_cast<float>(row) * tileSize, tileSize,
            tileSize};
}

TileRegion TileMap::tilesUnder(const hitbox::Box& box) const
{
    // BEGIN TASK 3: the tiles under a box (the swept-bounds broad phase)
    if (!hitbox::isFinite(box))
        return {};
    const hitbox::Box b = hitbox::normalised(box);
    // A tile index clipped to -1..count before it becomes an int: a huge coordinate must not
    // overflow, and outside the map on either side stays outside.
    auto clampToMap = [](float index, int count)
    { return static_cast<int>(std::clamp(index, -1.f, static_cast<float>(count))); };
    // A tile column c spans [c * size, (c + 1) * size). The box shares area with it when
    // left < (c + 1) * size and right > c * size: floor() on the left, ceil() - 1 on the right.
    TileRegion region;
    region.firstColumn = clampToMap(std::floor(b.left / tileSize), columns);
    region.lastColumn = clampToMap(std::ceil((b.left + b.width) / tileSize) - 1.f, columns);
    region.firstRow = clampToMap(std::floor(b.top / tileSize), rows);
    region.lastRow = clampToMap(std::ceil((b.top + b.height) / tileSize) - 1.f, rows);
    // Keep only the part inside the map (a box beside the map gives an empty region).
    region.firstColumn = std::max(region.firstColumn, 0);
    region.lastColumn = std::min(region.lastColumn, columns - 1);
    region.firstRow = std::max(region.firstRow, 0);
    region.lastRow = std::min(region.lastRow, rows - 1);
    return region;
    // STARTER TASK 3
    // (void)box; // every tile in the map: correct, but it tests them all, every step
    // return TileRegion{0, columns - 1, 0, rows - 1};
    // END TASK 3
}
