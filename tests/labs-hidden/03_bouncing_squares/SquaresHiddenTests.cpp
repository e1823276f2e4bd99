// Hidden variants of lab 3's grading tests: the same behaviour as SquaresGradingTests.cpp with
// other positions, speeds, directions and world sizes. The instructor's build and the class
// grader run them; the student handout leaves tests/labs-hidden/ out, so no one can tune an
// answer to them. As in the visible tests, each task's tests run only that task's code (the
// constructor's box, Square::update, bounceApart), so one mistake costs one task.
#include "labs/03_bouncing_squares/SquaresChecks.h"
#include "labs/LabTesting.h"

#include "Square.h"

#include "hitbox/app/Level.h"
#include "hitbox/app/Loop.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/Color.hpp>
#include <SFML/System/Vector2.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace
{

using namespace squareschecks;

// Is the square's collision box inside `world` (0.01 px allowed for rounding)?
bool boxInside(const Square& square, sf::Vector2f world)
{
    const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
    return box.left >= -0.01f && box.top >= -0.01f && box.left + box.width <= world.x + 0.01f &&
           box.top + box.height <= world.y + 0.01f;
}

// A world smaller than the default one, and not in its proportions: walls a square must find
// through setWorldSize, not through the numbers of the default window.
const sf::Vector2f smallWorld{517.f, 389.f};

} // namespace

TEST(Task1FitTheCollisionBoxToTheCrate, HiddenTheBoxIsTheCrateWhereverTheSquareStarts)
{
    // Squares started away from the middle, one partly off the window, all moving: the box
    // is measured from each square's own centre, not placed at fixed world coordinates.
    const sf::Vector2f centers[] = {{83.5f, 611.25f}, {-40.f, 25.f}, {1190.f, 3.f}};
    for (const sf::Vector2f center : centers)
    {
        const Square square(center, {-130.f, 75.f}, sf::Color::Green);
        const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
        EXPECT_FLOAT_EQ(box.width, crateSize) << "a square centred at " << labtesting::text(center);
        EXPECT_FLOAT_EQ(box.height, crateSize)
            << "a square centred at " << labtesting::text(center);
        EXPECT_VEC_NEAR(sf::Vector2f(box.left, box.top),
                        center - sf::Vector2f(crateSize, crateSize) / 2.f, 0.01f)
            << "a margin on the left and on top of the square centred at "
            << labtesting::text(center);
    }
}

TEST(Task1FitTheCollisionBoxToTheCrate, HiddenTheBoxStaysOnTheCrateWhenTheSquareMoves)
{
    // Moved and then placed elsewhere after it was made: the box goes with the square, and
    // stays the crate's size, smaller than the picture on every side.
    Square square({250.f, 140.f}, {}, sf::Color::Blue);
    square.move({-97.5f, 310.f});
    EXPECT_VEC_NEAR(labtesting::centerOf(square.getCollisionBox()), sf::Vector2f(152.5f, 450.f),
                    0.01f);
    square.setPosition({1033.f, 77.75f});
    const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
    const hitbox::Box picture = hitbox::toBox(square.getGlobalBounds());
    EXPECT_VEC_NEAR(labtesting::centerOf(square.getCollisionBox()), sf::Vector2f(1033.f, 77.75f),
                    0.01f);
    EXPECT_NEAR(box.left - picture.left, margin, 0.01f) << "the margin on the left";
    EXPECT_NEAR(box.top - picture.top, margin, 0.01f) << "the margin on top";
    EXPECT_FLOAT_EQ(box.width, crateSize);
    EXPECT_FLOAT_EQ(box.height, crateSize);
}

TEST(Task2BounceTheBoxOffTheWalls, HiddenInASmallerWorldTheCrateTurnsAtThatWorldsEdges)
{
    // A smaller world, reached at its bottom and then its right edge: the crate bounces off
    // the walls setWorldSize gave it, touching them while its margin hangs over. Walls
    // written as the default window's numbers let it fly out.
    Square square = crate({300.f, 200.f}, {190.f, 260.f});
    square.setWorldSize(smallWorld);
    float furthestRight = 0.f;
    float furthestDown = 0.f;
    float furthestPicture = 0.f;
    for (int step = 0; step < stepsFor(1.1f); ++step)
    {
        square.update(hitbox::stepSeconds);
        ASSERT_TRUE(boxInside(square, smallWorld))
            << "after step " << step << " the crate is out of the " << smallWorld.x << " x "
            << smallWorld.y << " world";
        const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
        furthestRight = std::max(furthestRight, box.left + box.width);
        furthestDown = std::max(furthestDown, box.top + box.height);
        furthestPicture =
            std::max(furthestPicture, hitbox::toBox(square.getGlobalBounds()).left + spriteSize);
    }
    EXPECT_NEAR(furthestRight, smallWorld.x, 0.01f) << "the crate reaches the right edge";
    EXPECT_NEAR(furthestDown, smallWorld.y, 0.01f) << "and the bottom edge";
    EXPECT_NEAR(furthestPicture, smallWorld.x + margin, 0.01f)
        << "while the picture's margin goes past it";
    EXPECT_VEC_NEAR(square.getVelocity(), sf::Vector2f(-190.f, -260.f), 0.01f)
        << "it comes back from both at the speed it went";
    EXPECT_EQ(square.getHitCount(), 2) << "two walls, two hits";
}

TEST(Task2BounceTheBoxOffTheWalls, HiddenIntoTheTopLeftCornerItComesBackFromBothWalls)
{
    // From near a corner, not the middle, at uneven speeds, reaching the left and the top
    // wall in different steps: each part of the velocity turns round at its own wall, where
    // the crate's edge (not the picture's) touches.
    const sf::Vector2f world = hitbox::defaultWorldSize;
    Square square =
        crate(sf::Vector2f(crateSize, crateSize) / 2.f + sf::Vector2f{21.f, 47.f}, {-173.f, -97.f});
    float leftmost = world.x;
    float topmost = world.y;
    for (int step = 0; step < stepsFor(0.75f); ++step)
    {
        square.update(hitbox::stepSeconds);
        ASSERT_TRUE(boxInside(square, world)) << "after step " << step;
        const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
        leftmost = std::min(leftmost, box.left);
        topmost = std::min(topmost, box.top);
    }
    EXPECT_NEAR(leftmost, 0.f, 0.01f) << "the crate reaches the left wall";
    EXPECT_NEAR(topmost, 0.f, 0.01f) << "the crate reaches the top wall";
    EXPECT_VEC_NEAR(square.getVelocity(), sf::Vector2f(173.f, 97.f), 0.01f);
    EXPECT_EQ(square.getHitCount(), 2);
}

TEST(Task2BounceTheBoxOffTheWalls, HiddenStraightAtEachWallOfASmallerWorldItStaysOnItsLine)
{
    // From off the middle of a smaller world, at another speed, straight at each of its walls:
    // it comes back at the same speed, put back across the wall only, with one hit.
    const sf::Vector2f start{211.f, 163.f};
    const float speed = 137.f;
    const sf::Vector2f directions[] = {{1.f, 0.f}, {-1.f, 0.f}, {0.f, 1.f}, {0.f, -1.f}};
    const float toWalls[] = {smallWorld.x - crateSize / 2.f - start.x, start.x - crateSize / 2.f,
                             smallWorld.y - crateSize / 2.f - start.y, start.y - crateSize / 2.f};
    for (int i = 0; i < 4; ++i)
    {
        const sf::Vector2f direction = directions[i];
        Square square = crate(start, direction * speed);
        square.setWorldSize(smallWorld);
        // Long enough to reach that wall, not the one across from it.
        for (int step = 0; step < stepsFor(toWalls[i] / speed + 0.2f); ++step)
            square.update(hitbox::stepSeconds);
        EXPECT_VEC_NEAR(square.getVelocity(), -direction * speed, 0.01f)
            << "a square sent towards " << labtesting::text(direction);
        const sf::Vector2f along{std::abs(direction.y), std::abs(direction.x)};
        const sf::Vector2f moved = square.getPosition() - start;
        EXPECT_NEAR(moved.x * along.x + moved.y * along.y, 0.f, 0.001f)
            << "a square sent straight towards " << labtesting::text(direction) << " left its line";
        EXPECT_EQ(square.getHitCount(), 1)
            << "a square sent towards " << labtesting::text(direction);
    }
}

TEST(Task2BounceTheBoxOffTheWalls, HiddenACrateOutButMovingAwayKeepsGoingAway)
{
    // Past each wall (the left and top of the default world, the right and bottom of a
    // smaller one), already moving away and along the wall too: it keeps its velocity. A
    // sign flip turns it back in.
    const sf::Vector2f starts[] = {{crateSize / 2.f - 2.5f, 300.f},
                                   {450.f, crateSize / 2.f - 4.f},
                                   {smallWorld.x - crateSize / 2.f + 3.5f, 180.f},
                                   {260.f, smallWorld.y - crateSize / 2.f + 2.75f}};
    const sf::Vector2f velocities[] = {
        {150.f, -40.f}, {65.f, 180.f}, {-130.f, 35.f}, {-45.f, -170.f}};
    const sf::Vector2f worlds[] = {hitbox::defaultWorldSize, hitbox::defaultWorldSize, smallWorld,
                                   smallWorld};
    for (int i = 0; i < 4; ++i)
    {
        Square square = crate(starts[i], velocities[i]);
        square.setWorldSize(worlds[i]);
        square.update(hitbox::stepSeconds);
        EXPECT_VEC_NEAR(square.getVelocity(), velocities[i], 0.001f)
            << "a crate at " << labtesting::text(starts[i]) << " moving away from the wall";
    }
}

TEST(Task2BounceTheBoxOffTheWalls, HiddenSlidingAlongTheWallsOfASmallerWorldIsNoHit)
{
    // The edge rule: a crate exactly touching a wall of a smaller world, moving along it,
    // touches without colliding: no hit, no turn.
    const sf::Vector2f starts[] = {{smallWorld.x - crateSize / 2.f, 120.f},
                                   {400.f, smallWorld.y - crateSize / 2.f},
                                   {200.f, crateSize / 2.f},
                                   {crateSize / 2.f, 300.f}};
    const sf::Vector2f velocities[] = {{0.f, 150.f}, {-230.f, 0.f}, {230.f, 0.f}, {0.f, -150.f}};
    for (int i = 0; i < 4; ++i)
    {
        Square square = crate(starts[i], velocities[i]);
        square.setWorldSize(smallWorld);
        for (int step = 0; step < stepsFor(0.5f); ++step)
            square.update(hitbox::stepSeconds);
        EXPECT_EQ(square.getHitCount(), 0)
            << "a crate touching a wall at " << labtesting::text(starts[i])
            << " and sliding along it is not hitting it (touching is not colliding)";
        EXPECT_VEC_NEAR(square.getVelocity(), velocities[i], 0.001f);
    }
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, HiddenUpAndDownAtUnequalSpeedsTheySwapAndNeverOverlap)
{
    // Head on along y, not x, at unequal speeds and drifting sideways: they meet crate to
    // crate, swap their up-down velocities and keep their sideways ones. Turning each square
    // round (right for the equal speeds of the visible tests) gives the wrong speeds here.
    const sf::Vector2f middle = hitbox::defaultWorldSize / 2.f;
    const sf::Vector2f upperVelocity{25.f, 130.f};
    const sf::Vector2f lowerVelocity{-40.f, -310.f};
    std::vector<Square> squares{crate(middle - sf::Vector2f{0.f, 150.f}, upperVelocity),
                                crate(middle + sf::Vector2f{0.f, 150.f}, lowerVelocity)};
    float worstOverlap = 0.f;
    float closest = 10000.f;
    for (int step = 0; step < stepsFor(1.f); ++step)
    {
        stepApart(squares, 1);
        worstOverlap =
            std::max(worstOverlap, overlapOf(hitbox::toBox(squares[0].getCollisionBox()),
                                             hitbox::toBox(squares[1].getCollisionBox())));
        closest = std::min(closest, squares[1].getPosition().y - squares[0].getPosition().y);
    }
    EXPECT_LE(worstOverlap, overlapTolerance) << "after a step the crates may not overlap";
    EXPECT_NEAR(closest, crateSize, overlapTolerance)
        << "at the closest the crates touch: centres one crate apart, not one picture";
    EXPECT_VEC_NEAR(squares[0].getVelocity(), sf::Vector2f(upperVelocity.x, lowerVelocity.y),
                    0.01f);
    EXPECT_VEC_NEAR(squares[1].getVelocity(), sf::Vector2f(lowerVelocity.x, upperVelocity.y),
                    0.01f);
    EXPECT_EQ(squares[0].getHitCount(), 1);
    EXPECT_EQ(squares[1].getHitCount(), 1);
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, HiddenOverlappingLeastAlongYTheyArePushedApartAlongY)
{
    // The second crate overlaps the first from above, mostly sideways: the overlap is least
    // along y, so each is pushed half of it up or down (not along x), both are told, and
    // the up-down velocities swap.
    const sf::Vector2f at{431.5f, 262.25f};
    Square first = crate(at, {33.f, -90.f});
    Square second = crate(at + sf::Vector2f{-0.15f, -0.8f} * crateSize, {-12.f, 60.f});
    const float xFirst = first.getPosition().x;
    const float xSecond = second.getPosition().x;
    const float ySum = first.getPosition().y + second.getPosition().y;
    bounceApart(first, second);
    const hitbox::Box a = hitbox::toBox(first.getCollisionBox());
    const hitbox::Box b = hitbox::toBox(second.getCollisionBox());
    EXPECT_NEAR(a.top - (b.top + b.height), 0.f, 0.01f) << "afterwards the crates just touch";
    EXPECT_NEAR(first.getPosition().y + second.getPosition().y, ySum, 0.01f)
        << "each crate moves half the overlap, so their midpoint stays put";
    EXPECT_FLOAT_EQ(first.getPosition().x, xFirst) << "not pushed sideways";
    EXPECT_FLOAT_EQ(second.getPosition().x, xSecond) << "not pushed sideways";
    EXPECT_EQ(first.getHitCount(), 1);
    EXPECT_EQ(second.getHitCount(), 1);
    EXPECT_VEC_NEAR(first.getVelocity(), sf::Vector2f(33.f, 60.f), 0.01f);
    EXPECT_VEC_NEAR(second.getVelocity(), sf::Vector2f(-12.f, -90.f), 0.01f);
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, HiddenOverlappingUpAndDownButSeparatingKeepsVelocities)
{
    // Overlapping along y but already moving apart, slowly, and at different sideways
    // speeds: pushed apart, not bounced back together.
    const sf::Vector2f at{777.f, 190.5f};
    Square first = crate(at, {-50.f, -0.3f});
    Square second = crate(at + sf::Vector2f{0.2f, 0.75f} * crateSize, {80.f, 0.3f});
    bounceApart(first, second);
    EXPECT_VEC_NEAR(first.getVelocity(), sf::Vector2f(-50.f, -0.3f), 0.0001f);
    EXPECT_VEC_NEAR(second.getVelocity(), sf::Vector2f(80.f, 0.3f), 0.0001f);
    const hitbox::Box a = hitbox::toBox(first.getCollisionBox());
    const hitbox::Box b = hitbox::toBox(second.getCollisionBox());
    EXPECT_NEAR(b.top - (a.top + a.height), 0.f, 0.01f) << "but pushed apart until they touch";
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, HiddenCratesTouchingTopToBottomOrAtACornerAreLeftAlone)
{
    // The edge rule along y and at a corner: edges that meet, closing in, are touching, not
    // overlapping, so nothing happens.
    const sf::Vector2f at{512.f, 337.5f};
    const sf::Vector2f offsets[] = {{17.f, crateSize}, {-crateSize, -crateSize}};
    const sf::Vector2f velocities[] = {{0.f, 150.f}, {-110.f, -140.f}};
    for (int i = 0; i < 2; ++i)
    {
        Square first = crate(at, velocities[i]);
        Square second = crate(at + offsets[i], -velocities[i]);
        bounceApart(first, second);
        EXPECT_EQ(first.getHitCount(), 0)
            << "the second crate at offset " << labtesting::text(offsets[i]);
        EXPECT_EQ(second.getHitCount(), 0);
        EXPECT_VEC_NEAR(first.getPosition(), at, 0.0001f);
        EXPECT_VEC_NEAR(first.getVelocity(), velocities[i], 0.0001f);
        EXPECT_VEC_NEAR(second.getVelocity(), -velocities[i], 0.0001f);
    }
}

TEST(Task3BounceOffEachOtherBoxAgainstBox, HiddenANineSquareCrowdInASmallerWorldStaysApart)
{
    // Nine squares, 3 x 3, faster, in a smaller world (the test's own walls keep them in):
    // whatever the crowd, no two crates stay overlapping.
    const sf::Vector2f world{900.f, 560.f};
    const float speed = 300.f;
    std::vector<Square> squares;
    for (int i = 0; i < 9; ++i)
    {
        const labtesting::CrowdStart start = labtesting::crowdStart(i, 3, 3, world, speed);
        squares.push_back(crate(start.position, start.velocity));
    }
    // A square pushed out of one can be pushed into another in the same step; allow what
    // two squares close in one step.
    const float crowdTolerance = 2.f * speed * hitbox::stepSeconds + overlapTolerance;
    for (int step = 0; step < stepsFor(6.f); ++step)
    {
        stepApart(squares, 1, world);
        for (std::size_t i = 0; i < squares.size(); ++i)
            for (std::size_t j = i + 1; j < squares.size(); ++j)
                ASSERT_LE(overlapOf(hitbox::toBox(squares[i].getCollisionBox()),
                                    hitbox::toBox(squares[j].getCollisionBox())),
                          crowdTolerance)
                    << "squares " << i << " and " << j << " at step " << step;
    }
}
