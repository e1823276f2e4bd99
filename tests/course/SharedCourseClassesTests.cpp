// The course's GameState, and the tile placing rule both generations' TileMap share
// (framework/compat/CourseGameState.h, CourseTileMap.h), on the older framework's GameObject:
// what a lab's menu and tile level see. (A whole TileMap holds an sf::Texture, which needs a
// display; scripts/check-course-labs.sh runs the tile-map labs under one.)
#include "support/SfmlPrinters.h"

#include "compat/CourseTileMap.h"
#include "compat/Framework/GameObject.h"
#include "compat/Framework/GameState.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{

// Tile 0 is the blank one, as the course's labs make it; 1 and 2 are solid.
std::vector<GameObject> threeTiles()
{
    std::vector<GameObject> tiles(3);
    for (GameObject& tile : tiles)
        tile.setSize({32.f, 16.f});
    tiles[2].setFillColor(sf::Color::Red);
    return tiles;
}

} // namespace

TEST(CourseTileMap, EachCellsTileSitsAtThePositionPlusColumnAndRowTimesTileZerosSize)
{
    const std::vector<GameObject> level =
        placeTiles(threeTiles(), {1, 0, 2, 2, 1, 0}, sf::Vector2u(3, 2), {100.f, 400.f}, nullptr);

    ASSERT_EQ(level.size(), 6u); // the blank tile is placed too: it is in the set
    EXPECT_EQ(level[0].getPosition(), sf::Vector2f(100.f, 400.f));
    EXPECT_EQ(level[2].getPosition(), sf::Vector2f(164.f, 400.f));
    EXPECT_EQ(level[2].getFillColor(), sf::Color::Red);
    EXPECT_EQ(level[3].getPosition(), sf::Vector2f(100.f, 416.f));
    EXPECT_EQ(level[5].getPosition(), sf::Vector2f(164.f, 416.f));
}

TEST(CourseTileMap, IndicesOutsideTheSetAndCellsPastTheMapsEndStayEmpty)
{
    // Four columns, two rows, but only five indices: the last three cells have none.
    const std::vector<GameObject> level =
        placeTiles(threeTiles(), {-1, 1, 3, 2, 1}, sf::Vector2u(4, 2), {0.f, 0.f}, nullptr);

    ASSERT_EQ(level.size(), 3u);
    EXPECT_EQ(level[0].getPosition(), sf::Vector2f(32.f, 0.f));
    EXPECT_EQ(level[1].getPosition(), sf::Vector2f(96.f, 0.f));
    EXPECT_EQ(level[2].getPosition(), sf::Vector2f(0.f, 16.f));
}

TEST(CourseTileMap, AnEmptySetOrAMapOfNoColumnsPlacesNothing)
{
    EXPECT_TRUE(placeTiles(std::vector<GameObject>(), {1, 1}, sf::Vector2u(2, 1), {}, nullptr).empty());
    EXPECT_TRUE(placeTiles(threeTiles(), {1, 1}, sf::Vector2u(0, 2), {}, nullptr).empty());
}

TEST(CourseGameState, StartsOnTheFirstStateAndKeepsTheOneSet)
{
    GameState gameState;
    EXPECT_EQ(gameState.getCurrentState(), State::MENU);
    gameState.setCurrentState(State::PAUSE);
    EXPECT_EQ(gameState.getCurrentState(), State::PAUSE);
}
