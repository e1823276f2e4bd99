// Data locality in lab 8 (BallOrder.h): sorting the balls into strips keeps every ball, puts
// them in strip-then-tile order, keeps the order inside a tile, and has an answer for balls
// outside the area, NaN positions and silly tile sizes. (Not a task's test: the starter passes
// it too.)
#include "BallOrder.h"
#include "ManyObjectsLevel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace
{

const hitbox::Box area{0.f, 0.f, 100.f, 50.f}; // 10 x 5 tiles of 10

// A ball whose velocity.x tags it, so a test can tell which ball went where.
Ball ballAt(float x, float y, float tag)
{
    Ball ball;
    ball.position = {x, y};
    ball.velocity = {tag, 0.f};
    return ball;
}

std::vector<float> tags(const std::vector<Ball>& balls)
{
    std::vector<float> result;
    for (const Ball& ball : balls)
        result.push_back(ball.velocity.x);
    return result;
}

} // namespace

TEST(BallOrder, SortsByStripTopToBottomThenByTileLeftToRight)
{
    std::vector<Ball> balls = {ballAt(95.f, 45.f, 5.f), ballAt(15.f, 25.f, 3.f),
                               ballAt(55.f, 5.f, 2.f), ballAt(65.f, 25.f, 4.f),
                               ballAt(5.f, 5.f, 1.f)};
    sortBallsByTile(balls, area, 10.f);
    EXPECT_EQ(tags(balls), (std::vector<float>{1.f, 2.f, 3.f, 4.f, 5.f}));
}

TEST(BallOrder, BallsInOneTileKeepTheirOrder)
{
    // Same tile (10 to 20, 0 to 10), given right to left: a stable sort leaves them so.
    std::vector<Ball> balls = {ballAt(19.f, 1.f, 1.f), ballAt(50.f, 45.f, 9.f),
                               ballAt(15.f, 9.f, 2.f), ballAt(11.f, 5.f, 3.f)};
    sortBallsByTile(balls, area, 10.f);
    EXPECT_EQ(tags(balls), (std::vector<float>{1.f, 2.f, 3.f, 9.f}));
}

TEST(BallOrder, ATileEdgeBelongsToTheTileItStarts)
{
    // x = 10 is the left edge of the second tile, y = 10 the top of the second strip.
    std::vector<Ball> balls = {ballAt(10.f, 0.f, 2.f), ballAt(9.999f, 0.f, 1.f),
                               ballAt(0.f, 10.f, 3.f)};
    sortBallsByTile(balls, area, 10.f);
    EXPECT_EQ(tags(balls), (std::vector<float>{1.f, 2.f, 3.f}));
}

TEST(BallOrder, BallsOutsideTheAreaOrAtNaNGoToTheEdgeTiles)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float huge = std::numeric_limits<float>::max();
    std::vector<Ball> balls = {ballAt(huge, huge, 5.f), ballAt(55.f, 25.f, 4.f),
                               ballAt(nan, 5.f, 1.f),   ballAt(-1e30f, 45.f, 3.f),
                               ballAt(15.f, nan, 2.f),  ballAt(-5.f, -5.f, 0.f)};
    sortBallsByTile(balls, area, 10.f);
    // (NaN, 5) and then (-5, -5) in tile (0, 0), in the order given; (15, NaN) in (1, 0);
    // (55, 25) in (5, 2); (-1e30, 45) in (0, 4); (huge, huge) in the last tile.
    EXPECT_EQ(tags(balls), (std::vector<float>{1.f, 0.f, 2.f, 4.f, 3.f, 5.f}));
}

TEST(BallOrder, EveryBallIsKeptWhateverTheTileSize)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float tileSizes[] = {
        0.f, -3.f, nan, 1e-30f, 7.f, 1e30f, std::numeric_limits<float>::infinity()};
    const hitbox::Box areas[] = {area, {0.f, 0.f, 0.f, 0.f}, {0.f, 0.f, 1e30f, 1.f}};
    for (const hitbox::Box& where : areas)
        for (float tileSize : tileSizes)
        {
            std::vector<Ball> balls;
            for (int i = 0; i < 200; ++i)
                balls.push_back(ballAt(float(i * 37 % 101), float(i * 53 % 49), float(i)));
            sortBallsByTile(balls, where, tileSize);
            std::vector<float> found = tags(balls);
            std::sort(found.begin(), found.end());
            ASSERT_EQ(found.size(), 200u) << "tile size " << tileSize;
            for (std::size_t i = 0; i < found.size(); ++i)
                ASSERT_EQ(found[i], float(i)) << "tile size " << tileSize;
        }
    std::vector<Ball> none;
    sortBallsByTile(none, area, 10.f);
    EXPECT_TRUE(none.empty());
}

TEST(BallOrder, AnAreaThatIsNotFiniteLeavesTheOrderAlone)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    const hitbox::Box areas[] = {{0.f, 0.f, nan, 50.f}, {0.f, 0.f, 100.f, infinity}};
    for (const hitbox::Box& where : areas)
    {
        std::vector<Ball> balls = {ballAt(95.f, 45.f, 1.f), ballAt(5.f, 5.f, 2.f)};
        sortBallsByTile(balls, where, 10.f);
        EXPECT_EQ(tags(balls), (std::vector<float>{1.f, 2.f}));
    }
}

TEST(BallOrder, ANewCrowdStartsSortedIntoStrips)
{
    LabSettings settings;
    settings.balls = 3000;
    settings.threads = 1;
    const ManyObjectsLevel level(settings);
    const std::vector<Ball>& balls = level.getBalls();
    ASSERT_EQ(balls.size(), 3000u);
    // No ball is in a strip above the ball before it.
    std::size_t outOfOrder = 0;
    for (std::size_t i = 1; i < balls.size(); ++i)
        outOfOrder += std::floor(balls[i].position.y / crowdSortTile) <
                              std::floor(balls[i - 1].position.y / crowdSortTile)
                          ? 1
                          : 0;
    EXPECT_EQ(outOfOrder, 0u);
}
