// Fuzz target: lab 9's level parser (TileMap::parse) fed any bytes.
// A level either loads and keeps its promises (every row as long as the first, the player
// start inside the map on an empty tile) or is refused with ONE printable line. Anything
// else - a crash, a sanitizer report, another exception, a raw byte in the message - is a
// bug, and its input is kept in corpus/level/ as a regression test.
#include "TileMap.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace
{
bool isOnePrintableLine(const std::string& message)
{
    for (const char c : message)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
            return false;
    return true;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    try
    {
        const TileMap map = TileMap::parse(text, "fuzz.txt");
        const hitbox::Vec2 start = map.getPlayerStart();
        const int column = static_cast<int>(start.x / TileMap::tileSize);
        const int row = static_cast<int>(start.y / TileMap::tileSize);
        if (map.getRows() < 1 || map.getColumns() < 1 || column >= map.getColumns() ||
            row >= map.getRows() || map.isSolid(column, row))
            std::abort();
    }
    catch (const LevelFileError& error)
    {
        if (!isOnePrintableLine(error.what()))
            std::abort();
    }
    return 0;
}
