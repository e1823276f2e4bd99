// Lab 9's level files: what a good file gives, what a broken one says, and (Task 3) which
// tiles lie under a box.
#include "TileMap.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
// The message of the LevelFileError that parsing `text` throws ("" if it throws none).
std::string parseError(const std::string& text)
{
    try
    {
        TileMap::parse(text, "levels/broken.txt");
    }
    catch (const LevelFileError& error)
    {
        return error.what();
    }
    return "";
}

testing::AssertionResult mentions(const std::string& message, const std::string& part)
{
    if (message.find(part) != std::string::npos)
        return testing::AssertionSuccess();
    return testing::AssertionFailure() << "'" << message << "' does not mention '" << part << "'";
}
} // namespace

TEST(LevelFile, ReadsSolidTilesEmptyTilesAndTheStart)
{
    const TileMap map = TileMap::parse("####\n#.P#\n####\n", "test");
    EXPECT_EQ(map.getColumns(), 4);
    EXPECT_EQ(map.getRows(), 3);
    EXPECT_TRUE(map.isSolid(0, 0));
    EXPECT_FALSE(map.isSolid(1, 1));
    EXPECT_FALSE(map.isSolid(2, 1)) << "the start is an empty tile";
    EXPECT_EQ(map.getPlayerStart(), hitbox::Vec2(96.f, 48.f));
    EXPECT_FALSE(map.isSolid(-1, 0)) << "outside the map there is nothing";
}

TEST(LevelFile, ReadsOneWayPlatformsSlopesAndCheckpoints)
{
    const TileMap map = TileMap::parse("#####\n#-/\\#\n#CP.#\n#####\n", "test");
    EXPECT_EQ(map.tileAt(1, 1), Tile::OneWay);
    EXPECT_EQ(map.tileAt(2, 1), Tile::SlopeUp);
    EXPECT_EQ(map.tileAt(3, 1), Tile::SlopeDown);
    EXPECT_EQ(map.tileAt(1, 2), Tile::Checkpoint);
    EXPECT_EQ(map.tileAt(2, 2), Tile::Empty) << "the start is an empty tile";
    EXPECT_EQ(map.tileAt(0, 0), Tile::Solid);
    EXPECT_EQ(map.tileAt(5, 0), Tile::Empty) << "outside the map there is nothing";
    // Only '#' is tested with the collision points: the others have their own rules.
    for (int column = 1; column <= 3; ++column)
        EXPECT_FALSE(map.isSolid(column, 1));
    EXPECT_FALSE(map.isSolid(1, 2));
}

TEST(LevelFile, ReadsWindowsLineEnds)
{
    const TileMap map = TileMap::parse("###\r\n#P#\r\n###\r\n", "test");
    EXPECT_EQ(map.getColumns(), 3);
    EXPECT_EQ(map.getRows(), 3);
}

TEST(LevelFile, UnknownTileNamesTheFileTheLineAndTheCharacter)
{
    const std::string message = parseError("####\n#.P#\n#.x#\n####\n");
    EXPECT_TRUE(mentions(message, "levels/broken.txt"));
    EXPECT_TRUE(mentions(message, "line 3"));
    EXPECT_TRUE(mentions(message, "'x'"));
    EXPECT_TRUE(mentions(message, "column 3"));
}

TEST(LevelFile, ShortRowNamesItsLineAndTheExpectedLength)
{
    const std::string message = parseError("####\n#.P#\n#.#\n####\n");
    EXPECT_TRUE(mentions(message, "line 3"));
    EXPECT_TRUE(mentions(message, "3 tiles"));
    EXPECT_TRUE(mentions(message, "has 4"));
}

TEST(LevelFile, TwoStartsNameBothLines)
{
    const std::string message = parseError("####\n#.P#\n#P.#\n####\n");
    EXPECT_TRUE(mentions(message, "line 3"));
    EXPECT_TRUE(mentions(message, "line 2"));
}

TEST(LevelFile, NoStartOrNoRowsIsReported)
{
    EXPECT_TRUE(mentions(parseError("####\n#..#\n####\n"), "player start"));
    EXPECT_TRUE(mentions(parseError("\n\n"), "no rows"));
}

TEST(LevelFile, MissingFileNamesThePathAndTheFix)
{
    try
    {
        TileMap::load("levels/no_such_level.txt");
        FAIL() << "loading a missing level should throw";
    }
    catch (const hitbox::AssetError& error)
    {
        EXPECT_TRUE(mentions(error.what(), "levels/no_such_level.txt"));
        EXPECT_TRUE(mentions(error.what(), "Fix"));
    }
}

TEST(LevelFile, TheLabsLevelLoads)
{
    const TileMap map = TileMap::load("levels/platformer.txt");
    EXPECT_GT(map.getColumns(), 20);
    EXPECT_GT(map.getRows(), 10);
}

// ---- Task 3: the tiles under a box ---------------------------------------------------------

namespace
{
const TileMap tenByTen = TileMap::parse(
    std::string(10, '#') + "\n" + std::string("#P") + std::string(8, '.') + "\n" +
        []
        {
            std::string rows;
            for (int row = 0; row < 8; ++row)
                rows += std::string(10, '.') + "\n";
            return rows;
        }(),
    "test");

void expectRegion(const TileRegion& region, int firstColumn, int lastColumn, int firstRow,
                  int lastRow)
{
    EXPECT_EQ(region.firstColumn, firstColumn);
    EXPECT_EQ(region.lastColumn, lastColumn);
    EXPECT_EQ(region.firstRow, firstRow);
    EXPECT_EQ(region.lastRow, lastRow);
}
} // namespace

TEST(Task3TilesUnder, ABoxInsideOneTileCoversOnlyThatTile)
{
    expectRegion(tenByTen.tilesUnder({100.f, 60.f, 10.f, 10.f}), 2, 2, 1, 1);
}

TEST(Task3TilesUnder, ABoxAcrossTileEdgesCoversEveryTileItReaches)
{
    expectRegion(tenByTen.tilesUnder({90.f, 40.f, 60.f, 60.f}), 1, 3, 0, 2);
}

TEST(Task3TilesUnder, AnEdgeExactlyOnATileBoundaryDoesNotReachTheNextTile)
{
    // 96..144 by 48..96 is exactly tile (2, 1): touching its neighbours is not sharing area.
    expectRegion(tenByTen.tilesUnder({96.f, 48.f, 48.f, 48.f}), 2, 2, 1, 1);
}

TEST(Task3TilesUnder, IsClippedToTheMapAndEmptyBesideIt)
{
    expectRegion(tenByTen.tilesUnder({-50.f, -50.f, 100.f, 100.f}), 0, 1, 0, 1);
    EXPECT_TRUE(tenByTen.tilesUnder({-500.f, 40.f, 100.f, 10.f}).isEmpty());
    EXPECT_TRUE(tenByTen.tilesUnder({1e30f, 40.f, 10.f, 10.f}).isEmpty());
}

TEST(Task3TilesUnder, ABoxPastTheFarEdgesEndsAtTheLastColumnAndRow)
{
    // The map is 480 x 480 pixels; this box reaches 40 pixels past its right and bottom.
    expectRegion(tenByTen.tilesUnder({400.f, 400.f, 120.f, 120.f}), 8, 9, 8, 9);
    // Inside the map, touching its right and bottom edges: still the last column and row.
    expectRegion(tenByTen.tilesUnder({432.f, 432.f, 48.f, 48.f}), 9, 9, 9, 9);
}
