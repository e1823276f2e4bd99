// Lab 9's level limits (issue 25, items 6 and 7): a level beyond the range the collision
// maths is exact for is refused when read, and the player never starts inside a tile.
#include "PlatformerTestSupport.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Range.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace
{
std::string parseError(const std::string& text)
{
    try
    {
        TileMap::parse(text, "test");
    }
    catch (const LevelFileError& error)
    {
        return error.what();
    }
    return "";
}

// A level `columns` wide and `rows` tall: the player start top left, a floor under it.
std::string level(int columns, int rows)
{
    std::string text = "P" + std::string(static_cast<std::size_t>(columns - 1), '.') + "\n";
    for (int row = 1; row < rows; ++row)
        text += std::string(static_cast<std::size_t>(columns), '#') + "\n";
    return text;
}
} // namespace

TEST(LevelLimits, TheWidestAndTallestLevelWithinTheExactRangeLoads)
{
    EXPECT_EQ(TileMap::parse(level(TileMap::maxTilesAcross, 2), "test").getColumns(),
              TileMap::maxTilesAcross);
    EXPECT_EQ(TileMap::parse(level(1, TileMap::maxTilesAcross), "test").getRows(),
              TileMap::maxTilesAcross);
    // The far corner, with room for a player falling out, is inside the exact range.
    EXPECT_LE((TileMap::maxTilesAcross + 6) * TileMap::tileSize, hitbox::exactRange);
}

TEST(LevelLimits, ALevelBeyondTheExactRangeIsRefusedWithTheLimit)
{
    const std::string wide = parseError(level(TileMap::maxTilesAcross + 1, 2));
    EXPECT_NE(wide.find("line 1: the level is over 20000 tiles wide"), std::string::npos) << wide;
    const std::string tall = parseError(level(1, TileMap::maxTilesAcross + 1));
    EXPECT_NE(tall.find("line 20001: the level is over 20000 tiles tall"), std::string::npos)
        << tall;
}

// (Only where it starts: falling is the tasks' work, and a test of no task must pass on the
// student's starter code.)
TEST(PlayerStart, UnderASolidTileThePlayerStartsBelowIt)
{
    platformertest::Game game("#####\n"
                              "#.P.#\n"
                              "#...#\n"
                              "#...#\n"
                              "#####\n");
    EXPECT_FALSE(hitbox::boxVsBox(game.level.getPlayer().getBox(), {0.f, 0.f, 240.f, 48.f}))
        << "the player's head is inside the ceiling";
    EXPECT_GE(game.position().y, TileMap::tileSize);
}

TEST(PlayerStart, AOneTileGapAroundTheStartIsRefused)
{
    try
    {
        PlatformerLevel level(TileMap::parse("####\n#P.#\n####\n", "test"));
        FAIL() << "a player start with no room for the player was accepted";
    }
    catch (const std::invalid_argument& error)
    {
        EXPECT_NE(std::string(error.what()).find("solid tiles above and below"), std::string::npos)
            << error.what();
    }
}

TEST(PlayerStart, AOneTileGapAroundACheckpointIsRefused)
{
    // The player restarts at a checkpoint as at 'P': it needs the same room.
    try
    {
        PlatformerLevel level(TileMap::parse("#####\n#...#\n#####\n#CP.#\n##.##\n", "test"));
        FAIL() << "a checkpoint with no room for the player was accepted";
    }
    catch (const std::invalid_argument& error)
    {
        EXPECT_NE(std::string(error.what()).find("the checkpoint 'C' (column 2, row 4)"),
                  std::string::npos)
            << error.what();
    }
}
