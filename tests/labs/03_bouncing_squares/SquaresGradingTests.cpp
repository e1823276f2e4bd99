// Grading tests of lab 3 (bouncing squares). Each suite is named after the task it checks;
// README.md lists them. No window, one fixed step at a time. Each task's tests run only that
// task's code (the constructor's box, Square::update, bounceApart), with whatever else they
// need set up by the test, so one mistake costs one task.
#include "labs/03_bouncing_squares/SquaresChecks.h"
#include "labs/LabTesting.h"
#include "support/CollisionMatchers.h"

#include "Square.h"
#include "SquaresLevel.h"

#include "hitbox/app/App.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

// The tests do not depend on the numbers at the top of Square.h (students are invited to
// change them): each test sets up its own squares at its own speed and places them by
// spriteSize and crateSize, so every test checks the same thing whatever those numbers are.
namespace
{

using namespace squareschecks;

// The speed the tests give their squares (pixels per second): slow enough that a test
// decides when a square reaches a wall.
constexpr float testSpeed = 220.f;

float dotOf(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.x + a.y * b.y;
}
// How far a square moves in one step.
constexpr float stepDistance = testSpeed * hitbox::stepSeconds;

// Task 2's tests: one square alone, moved by its own update (task 2's code), step by step.
void run(Square& square, int steps)
{
    for (int step = 0; step < steps; ++step)
        square.update(hitbox::stepSeconds);
}

// The lecture's example: two squares on one line, flying at each other at testSpeed.
std::vector<Square> twoSquaresFlyingAtEachOther()
{
    return {crate({hitbox::defaultWorldSize.x * 0.25f, hitbox::defaultWorldSize.y / 2.f},
                  {testSpeed, 0.f}),
            crate({hitbox::defaultWorldSize.x * 0.75f, hitbox::defaultWorldSize.y / 2.f},
                  {-testSpeed, 0.f})};
}

const sf::Vector2f middle{600.f, 337.5f};

} // namespace

TEST(Level, StartsWithTwoSquaresFlyingAtEachOther)
{
    SquaresLevel level;
    ASSERT_EQ(level.getSquareCount(), 2);
    EXPECT_FLOAT_EQ(level.getSquare(0).getVelocity().x, squareSpeed);
    EXPECT_FLOAT_EQ(level.getSquare(1).getVelocity().x, -squareSpeed);
    EXPECT_EQ(level.getSquare(0).getSize(), sf::Vector2f(spriteSize, spriteSize))
        << "the shape is the whole picture";
}

TEST(Task1FitTheCollisionBoxToTheCrate, TheBoxIsTheCrateNotTheWholePicture)
{
    const Square square(middle, {}, sf::Color::Red);
    const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
    EXPECT_FLOAT_EQ(box.width, crateSize);
    EXPECT_FLOAT_EQ(box.height, crateSize);
    EXPECT_LT(box.width, hitbox::toBox(square.getGlobalBounds()).width)
        << "smaller than the sprite";
}

TEST(Task1FitTheCollisionBoxToTheCrate, TheBoxIsCentredOnThePicture)
{
    const Square square(middle, {}, sf::Color::Red);
    EXPECT_VEC_NEAR(labtesting::centerOf(square.getCollisionBox()), middle, 0.01f);
    const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
    EXPECT_NEAR(box.left, middle.x - crateSize / 2.f, 0.01f) << "a margin on the left...";
    EXPECT_NEAR(box.top, middle.y - crateSize / 2.f, 0.01f) << "...and on top";
}

TEST(Task2BounceTheBoxOffTheWalls, SquareNeverLeavesTheWindow)
{
    Square square = crate(middle, {testSpeed * 1.2f, testSpeed * 0.8f});
    const sf::Vector2f world = hitbox::defaultWorldSize;
    for (int step = 0; step < 20 * 120; ++step)
    {
        run(square, 1);
        // The window, 0.01 px larger all round (rounding).
        ASSERT_THAT(square, hitbox::testing::StaysInside(
                                {-0.01f, -0.01f, world.x + 0.02f, world.y + 0.02f}))
            << "after step " << step << " the collision box sticks out of the window";
    }
}

TEST(Task2BounceTheBoxOffTheWalls, TheCrateTouchesTheWallWhileTheMarginGoesPastIt)
{
    // Bounce on the box, not the sprite: at the turn the crate reaches the wall and the
    // see-through margin hangs over it.
    Square square = crate(middle, {testSpeed, 0.f});
    const float world = hitbox::defaultWorldSize.x;
    // Long enough to reach the right wall, not the left one.
    const float seconds = (world / 2.f - crateSize / 2.f) / testSpeed + 0.5f;
    float furthestPicture = 0.f;
    float furthestBox = 0.f;
    for (int step = 0; step < stepsFor(seconds); ++step)
    {
        run(square, 1);
        furthestPicture =
            std::max(furthestPicture, hitbox::toBox(square.getGlobalBounds()).left + spriteSize);
        const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
        furthestBox = std::max(furthestBox, box.left + box.width);
    }
    EXPECT_NEAR(furthestBox, world, 0.01f) << "the crate reaches the right edge";
    EXPECT_NEAR(furthestPicture, world + margin, 0.01f)
        << "the picture's margin goes past the edge by " << margin << " pixels";
    EXPECT_FLOAT_EQ(square.getVelocity().x, -testSpeed) << "and it came back";
    EXPECT_EQ(square.getHitCount(), 1) << "the wall is one hit";
}

TEST(Task2BounceTheBoxOffTheWalls, SquareComesBackFromEachWallAtTheSameSpeed)
{
    const sf::Vector2f directions[] = {{1.f, 0.f}, {-1.f, 0.f}, {0.f, 1.f}, {0.f, -1.f}};
    for (sf::Vector2f direction : directions)
    {
        Square square = crate(middle, direction * testSpeed);
        // Long enough to reach the wall it flies at, not the one across from it.
        const sf::Vector2f toWall =
            hitbox::defaultWorldSize / 2.f - sf::Vector2f(crateSize, crateSize) / 2.f;
        run(square,
            stepsFor(std::abs(toWall.x * direction.x + toWall.y * direction.y) / testSpeed + 0.3f));
        EXPECT_VEC_NEAR(square.getVelocity(), -direction * testSpeed, 0.01f)
            << "a square sent towards " << labtesting::text(direction);
        // Put back only across the wall: along it, it stays on its line.
        const sf::Vector2f along{std::abs(direction.y), std::abs(direction.x)};
        EXPECT_NEAR(dotOf(square.getPosition() - middle, along), 0.f, 0.001f)
            << "a square sent straight towards " << labtesting::text(direction) << " left its line";
        EXPECT_EQ(square.getHitCount(), 1) << "each wall bounce is one hit it is told about";
    }
}

TEST(Task2BounceTheBoxOffTheWalls, ASquareAlreadyOnItsWayBackIsNotTurnedIntoTheWall)
{
    // Its box 3 px past the right (bottom) wall but already moving away: it keeps going
    // away. A sign flip (velocity = -velocity) would turn it back into the wall.
    const sf::Vector2f world = hitbox::defaultWorldSize;
    const sf::Vector2f starts[] = {{world.x - crateSize / 2.f + 3.f, middle.y},
                                   {middle.x, world.y - crateSize / 2.f + 3.f}};
    const sf::Vector2f velocities[] = {{-testSpeed, 0.f}, {0.f, -testSpeed}};
    for (int i = 0; i < 2; ++i)
    {
        Square square = crate(starts[i], velocities[i]);
        run(square, 1);
        EXPECT_VEC_NEAR(square.getVelocity(), velocities[i], 0.001f)
            << "a crate at " << labtesting::text(starts[i]) << " moving away from the wall";
    }
}

TEST(Task2BounceTheBoxOffTheWalls, SquareSlidingAlongAWallIsNotHittingIt)
{
    // The edge rule: touching is not colliding. A crate exactly touching the top wall (and
    // one touching the left wall), moving along it, never hits it: with <= instead of < it
    // would "hit" every step and flash all the time.
    const sf::Vector2f world = hitbox::defaultWorldSize;
    const sf::Vector2f starts[] = {{middle.x, crateSize / 2.f},
                                   {crateSize / 2.f, middle.y},
                                   {middle.x, world.y - crateSize / 2.f},
                                   {world.x - crateSize / 2.f, middle.y}};
    const sf::Vector2f velocities[] = {
        {testSpeed, 0.f}, {0.f, testSpeed}, {-testSpeed, 0.f}, {0.f, -testSpeed}};
    for (int i = 0; i < 4; ++i)
    {
        Square square = crate(starts[i], velocities[i]);
        run(square, stepsFor(0.5f));
        EXPECT_EQ(square.getHitCount(), 0)
            << "a crate touching a wall at " << labtesting::text(starts[i])
            << " and sliding along it is not hitting it (touching is not colliding)";
        EXPECT_VEC_NEAR(square.getVelocity(), velocities[i], 0.001f);
    }
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, HeadOnSquaresSwapVelocitiesAndNeverOverlap)
{
    std::vector<Square> squares = twoSquaresFlyingAtEachOther();
    float worstOverlap = 0.f;
    int stepsSinceTheyMet = -1;
    // Until a quarter of a second after their crates meet: long enough to bounce.
    for (int step = 0; step < 4 * 120 && stepsSinceTheyMet < 30; ++step)
    {
        stepApart(squares, 1);
        const float overlap = overlapOf(hitbox::toBox(squares[0].getCollisionBox()),
                                        hitbox::toBox(squares[1].getCollisionBox()));
        worstOverlap = std::max(worstOverlap, overlap);
        const float apart = squares[1].getPosition().x - squares[0].getPosition().x;
        if (stepsSinceTheyMet >= 0 || apart < crateSize + 1.f)
            ++stepsSinceTheyMet;
    }
    ASSERT_GE(stepsSinceTheyMet, 0) << "the squares should meet within four seconds";
    EXPECT_LE(worstOverlap, overlapTolerance) << "after a step the crates may not overlap";
    EXPECT_FLOAT_EQ(squares[0].getVelocity().x, -testSpeed) << "the left square goes back left";
    EXPECT_FLOAT_EQ(squares[1].getVelocity().x, testSpeed) << "the right square goes back right";
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, SquaresBounceOnTheirCratesNotTheirPictures)
{
    // At the closest approach the crates touch: the centres are one crate apart, and the
    // see-through margins overlap.
    std::vector<Square> squares = twoSquaresFlyingAtEachOther();
    const float world = hitbox::defaultWorldSize.x;
    // Long enough to meet and part.
    const float seconds = (world / 2.f - crateSize) / (2.f * testSpeed) + 0.3f;
    float closest = 10000.f;
    for (int step = 0; step < stepsFor(seconds); ++step)
    {
        stepApart(squares, 1);
        closest =
            std::min(closest, std::abs(squares[1].getPosition().x - squares[0].getPosition().x));
    }
    EXPECT_NEAR(closest, crateSize, overlapTolerance)
        << "centres " << crateSize << " apart: crate touching crate (" << spriteSize
        << " would mean picture touching picture)";
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, BothSquaresAreToldAboutTheHit)
{
    Square first = crate(middle, {});
    Square second = crate(middle + sf::Vector2f{0.8f, 0.1f} * crateSize, {}); // overlapping
    bounceApart(first, second);
    EXPECT_EQ(first.getHitCount(), 1);
    EXPECT_EQ(second.getHitCount(), 1);
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, OverlappingCratesArePushedApartUntilTheyJustTouch)
{
    // Overlapping by 0.3 crate along x (less than along y): each moves half of it, out along x.
    Square first = crate(middle, {});
    Square second = crate(middle + sf::Vector2f{0.7f, 0.1f} * crateSize, {});
    bounceApart(first, second);
    const hitbox::Box a = hitbox::toBox(first.getCollisionBox());
    const hitbox::Box b = hitbox::toBox(second.getCollisionBox());
    EXPECT_NEAR(b.left - (a.left + a.width), 0.f, 0.01f) << "afterwards the crates just touch";
    EXPECT_NEAR(first.getPosition().x + second.getPosition().x, 2.f * middle.x + 0.7f * crateSize,
                0.01f)
        << "each crate moves half the overlap, so their midpoint stays put";
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, OverlappingCratesDriftingApartKeepTheirVelocities)
{
    // Overlapping but already separating, however slowly (0.4 px/s): pushed apart, not bounced.
    Square first = crate(middle, {-0.2f, 0.f});
    Square second = crate(middle + sf::Vector2f{0.7f, 0.1f} * crateSize, {0.2f, 0.f});
    bounceApart(first, second);
    EXPECT_FLOAT_EQ(first.getVelocity().x, -0.2f);
    EXPECT_FLOAT_EQ(second.getVelocity().x, 0.2f);
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, CratesOnlyTouchingAreLeftAlone)
{
    // The edge rule: centres exactly one crate apart, closing in: touching is not colliding.
    Square first = crate(middle, {testSpeed, 0.f});
    Square second = crate(middle + sf::Vector2f{crateSize, 0.f}, {-testSpeed, 0.f});
    bounceApart(first, second);
    EXPECT_EQ(first.getHitCount(), 0);
    EXPECT_EQ(second.getHitCount(), 0);
    EXPECT_FLOAT_EQ(first.getVelocity().x, testSpeed);
    EXPECT_FLOAT_EQ(second.getVelocity().x, -testSpeed);
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, LandingOnTopChangesOnlyTheUpDownVelocity)
{
    // A square falls onto one at rest, a little to the side: they meet top to bottom, so
    // the sideways velocity is kept and the downward one is passed on.
    const float gap = 40.f; // between the crates
    const sf::Vector2f falling{0.1f * testSpeed, testSpeed};
    std::vector<Square> squares{
        crate(middle - sf::Vector2f{0.2f * crateSize, crateSize + gap}, falling),
        crate(middle, {})};
    stepApart(squares, stepsFor(gap / testSpeed + 0.3f));
    EXPECT_VEC_NEAR(squares[0].getVelocity(), sf::Vector2f(falling.x, 0.f), 0.01f)
        << "the falling square keeps its sideways speed and stops falling";
    EXPECT_VEC_NEAR(squares[1].getVelocity(), sf::Vector2f(0.f, falling.y), 0.01f)
        << "the square at rest moves down at the falling square's speed, not sideways";
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, ManySquaresStayInsideAndApart)
{
    // Up to twelve squares spread over the window in a grid (4 x 3, fewer when the
    // pictures are too big for that), flying in as many directions; the test's own walls
    // keep them in (task 2's answer, written out in stepApart).
    const sf::Vector2f world = hitbox::defaultWorldSize;
    const int columns = std::clamp(static_cast<int>(world.x / (1.5f * spriteSize)), 2, 4);
    const int rows = std::clamp(static_cast<int>(world.y / (1.5f * spriteSize)), 1, 3);
    std::vector<Square> squares;
    for (int i = 0; i < columns * rows; ++i)
    {
        const labtesting::CrowdStart start =
            labtesting::crowdStart(i, columns, rows, world, testSpeed);
        squares.push_back(crate(start.position, start.velocity));
    }
    // In a crowd a square pushed out of one can be pushed into another (or past a wall) in
    // the same step; allow what two squares close in one step.
    const float crowdTolerance = 2.f * stepDistance + overlapTolerance;
    for (int step = 0; step < 10 * 120; ++step)
    {
        stepApart(squares, 1, world);
        for (std::size_t i = 0; i < squares.size(); ++i)
        {
            const hitbox::Box box = hitbox::toBox(squares[i].getCollisionBox());
            ASSERT_TRUE(box.left >= -crowdTolerance && box.top >= -crowdTolerance &&
                        box.left + box.width <= world.x + crowdTolerance &&
                        box.top + box.height <= world.y + crowdTolerance)
                << "square " << i << " left the window at step " << step;
            for (std::size_t j = i + 1; j < squares.size(); ++j)
                ASSERT_LE(overlapOf(box, hitbox::toBox(squares[j].getCollisionBox())),
                          crowdTolerance)
                    << "squares " << i << " and " << j << " at step " << step;
        }
    }
}
