// The debug renderer builds its lines without a window.
#include "support/SfmlPrinters.h"

#include "hitbox/debug/BroadphaseDrawing.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/objects/GameObject.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

TEST(DebugRenderer, ABoxIsFourLinesInOneArray)
{
    hitbox::DebugRenderer debug;
    debug.box({0.f, 0.f, 10.f, 10.f}, hitbox::DebugRenderer::freeColor);
    ASSERT_EQ(debug.getVertices().getVertexCount(), 4u * 6u); // two triangles a line
    EXPECT_EQ(debug.getVertices().getPrimitiveType(), sf::PrimitiveType::Triangles);
    EXPECT_EQ(debug.getVertices()[0].color, hitbox::DebugRenderer::freeColor);
}

// Opaque lines skip blending (same pixels, less work): one see-through line turns it off for
// the whole array until clear().
TEST(DebugRenderer, DrawsWithoutBlendingOnlyWhileEveryLineIsOpaque)
{
    hitbox::DebugRenderer debug;
    EXPECT_TRUE(debug.isOpaque());
    debug.box({0.f, 0.f, 10.f, 10.f}, hitbox::DebugRenderer::hintColor);
    debug.circle({{40.f, 40.f}, 5.f}, hitbox::DebugState::Overlapping);
    EXPECT_TRUE(debug.isOpaque());
    debug.line({0.f, 0.f}, {5.f, 5.f}, sf::Color(255, 255, 255, 254));
    EXPECT_FALSE(debug.isOpaque());
    debug.box({0.f, 0.f, 10.f, 10.f}, hitbox::DebugRenderer::hintColor);
    EXPECT_FALSE(debug.isOpaque());
    debug.clear();
    EXPECT_TRUE(debug.isOpaque());
}

TEST(DebugRenderer, AHairlineIsOnePixelAcrossALineTwo)
{
    hitbox::DebugRenderer debug;
    debug.line({0.f, 5.f}, {10.f, 5.f}, hitbox::DebugRenderer::hintColor);
    debug.hairline({0.f, 5.f}, {10.f, 5.f}, hitbox::DebugRenderer::hintColor);
    const sf::VertexArray& lines = debug.getVertices();
    ASSERT_EQ(lines.getVertexCount(), 2u * 6u);
    // The first two corners of each quad lie either side of `from`, the width apart.
    EXPECT_EQ(lines[0].position, sf::Vector2f(0.f, 4.f));
    EXPECT_EQ(lines[1].position, sf::Vector2f(0.f, 6.f));
    EXPECT_EQ(lines[6].position, sf::Vector2f(0.f, 4.5f));
    EXPECT_EQ(lines[7].position, sf::Vector2f(0.f, 5.5f));
    EXPECT_EQ(lines[6].color, hitbox::DebugRenderer::hintColor);
}

// A window shrunk to fit the screen shows 1.5 world units in a pixel: a hairline 1 unit wide
// would miss pixel centres and drop out, so it grows to one pixel; zoomed in it stays 1 unit.
TEST(DebugRenderer, AHairlineIsNeverThinnerThanAScreenPixel)
{
    const auto widthAt = [](float worldUnitsPerPixel)
    {
        hitbox::DebugRenderer debug;
        debug.setScreenPixel(worldUnitsPerPixel);
        debug.hairline({0.f, 5.f}, {10.f, 5.f}, hitbox::DebugRenderer::hintColor);
        return debug.getVertices()[1].position.y - debug.getVertices()[0].position.y;
    };
    EXPECT_FLOAT_EQ(widthAt(1.5f), 1.5f);
    EXPECT_FLOAT_EQ(widthAt(1.f), 1.f);
    EXPECT_FLOAT_EQ(widthAt(0.5f), 1.f);
    // Nonsense is ignored: the default, one unit.
    for (const float nonsense : {0.f, -2.f, std::numeric_limits<float>::infinity(),
                                 std::numeric_limits<float>::quiet_NaN()})
        EXPECT_FLOAT_EQ(widthAt(nonsense), 1.f) << nonsense;
    // Ordinary lines keep their 2 units whatever the pixel.
    hitbox::DebugRenderer debug;
    debug.setScreenPixel(1.5f);
    debug.line({0.f, 5.f}, {10.f, 5.f}, hitbox::DebugRenderer::hintColor);
    EXPECT_FLOAT_EQ(debug.getVertices()[1].position.y - debug.getVertices()[0].position.y, 2.f);
}

// A grid of small cells is drawn in hairlines, so it does not hide the boxes in its cells.
TEST(BroadphaseDrawing, GridLinesAreOnePixelWideBelowTwentyFourPixelCellsAndTwoFromThere)
{
    for (const float cell : {4.f, 10.f, 23.9f, 24.f, 40.f})
    {
        hitbox::BroadphaseLayout layout;
        layout.cellSize = cell;
        layout.columns = 2;
        layout.rows = 2;
        layout.boxesPerCell.assign(4, 0u); // no busy cells: the lines only
        hitbox::DebugRenderer debug;
        hitbox::drawBroadphase(debug, layout);
        const sf::VertexArray& lines = debug.getVertices();
        ASSERT_EQ(lines.getVertexCount(), 6u * 6u) << cell; // 3 columns' and 3 rows' lines
        const float expectedWidth = cell < 24.f ? 1.f : 2.f;
        for (std::size_t line = 0; line < 6; ++line)
        {
            const sf::Vector2f across = lines[line * 6 + 1].position - lines[line * 6].position;
            EXPECT_FLOAT_EQ(std::abs(across.x) + std::abs(across.y), expectedWidth)
                << "cell " << cell << ", line " << line;
        }
    }
}

TEST(BroadphaseDrawing, EachMethodsStructureIsDrawn)
{
    std::vector<hitbox::BroadphaseItem> items(20, hitbox::BroadphaseItem{{0.f, 0.f, 30.f, 30.f}});
    for (std::size_t i = 0; i < items.size(); ++i)
        items[i].box.left = 20.f * static_cast<float>(i);
    for (hitbox::BroadphaseMethod method :
         {hitbox::BroadphaseMethod::SortAndSweep, hitbox::BroadphaseMethod::Grid,
          hitbox::BroadphaseMethod::Quadtree})
    {
        auto broadphase = hitbox::makeBroadphase(method);
        std::vector<hitbox::Pair> pairs;
        broadphase->findPairs(items, pairs);
        hitbox::DebugRenderer debug;
        hitbox::drawBroadphase(debug, broadphase->layout());
        EXPECT_GT(debug.getVertices().getVertexCount(), 0u) << hitbox::toString(method);
    }
}

TEST(DebugRenderer, CollidingObjectsAreHatchedInTheOverlappingColourAndShowVelocity)
{
    hitbox::GameObject object;
    object.setSize({10.f, 10.f});
    object.setVelocity(100.f, 0.f);
    hitbox::DebugRenderer debug;
    debug.objectBox(object, true);
    const sf::VertexArray& lines = debug.getVertices();
    EXPECT_EQ(lines[0].color, hitbox::DebugRenderer::overlappingColor);
    // Last come the velocity arrow's shaft and its two head strokes (6 vertices a line): the
    // shaft runs from the centre a quarter second long, a 2-pixel quad around (5, 5)-(30, 5).
    const std::size_t shaft = lines.getVertexCount() - 3 * 6;
    EXPECT_EQ(lines[shaft].position, sf::Vector2f(5.f, 4.f));
    EXPECT_EQ(lines[shaft + 2].position, sf::Vector2f(30.f, 6.f));
    EXPECT_EQ(lines[shaft].color, hitbox::DebugRenderer::velocityColor);
}

TEST(DebugRenderer, EachStateHasItsOwnColourAndLineStyle)
{
    // Colour is never the only cue: a solid outline is 4 lines, a dashed one more and
    // shorter ones, a hatched one the 4 edges plus stripes across the box.
    const hitbox::Box box{0.f, 0.f, 40.f, 40.f};
    std::size_t lineCount[3] = {};
    const hitbox::DebugState states[3] = {hitbox::DebugState::Free, hitbox::DebugState::Touching,
                                          hitbox::DebugState::Overlapping};
    for (int i = 0; i < 3; ++i)
    {
        hitbox::DebugRenderer debug;
        debug.box(box, states[i]);
        lineCount[i] = debug.getVertices().getVertexCount() / 6;
        EXPECT_EQ(debug.getVertices()[0].color, hitbox::DebugRenderer::colorOf(states[i]));
    }
    EXPECT_EQ(lineCount[0], 4u);
    EXPECT_EQ(lineCount[1], 4u * 4u) << "each 40 px edge: dashes of 6 px every 10 px";
    EXPECT_GT(lineCount[2], 4u + 8u) << "hatching every 7 px across an 80 px diagonal span";
    EXPECT_NE(hitbox::DebugRenderer::freeColor, hitbox::DebugRenderer::touchingColor);
    EXPECT_NE(hitbox::DebugRenderer::touchingColor, hitbox::DebugRenderer::overlappingColor);
    // Circles too: dashed is half the arcs, hatched adds chords.
    hitbox::DebugRenderer solid, dashed, hatched;
    solid.circle(hitbox::Circle{{0.f, 0.f}, 20.f}, hitbox::DebugState::Free);
    dashed.circle(hitbox::Circle{{0.f, 0.f}, 20.f}, hitbox::DebugState::Touching);
    hatched.circle(hitbox::Circle{{0.f, 0.f}, 20.f}, hitbox::DebugState::Overlapping);
    EXPECT_EQ(dashed.getVertices().getVertexCount() * 2, solid.getVertices().getVertexCount());
    EXPECT_GT(hatched.getVertices().getVertexCount(), solid.getVertices().getVertexCount());
}

TEST(DebugRenderer, ThePanelCollectsLinesUntilCleared)
{
    hitbox::DebugRenderer debug;
    debug.panel({"first", "second"});
    debug.panel({"third"});
    EXPECT_EQ(debug.getPanel(), (std::vector<std::string>{"first", "second", "third"}));
    debug.clear();
    EXPECT_TRUE(debug.getPanel().empty());
}

TEST(DebugRenderer, ContactsDrawOnlyWhenHit)
{
    hitbox::DebugRenderer debug;
    debug.contact(hitbox::Contact{});
    EXPECT_EQ(debug.getVertices().getVertexCount(), 0u);
    debug.contact(hitbox::Contact{true, {0.f, -1.f}, 2.f, {5.f, 5.f}});
    EXPECT_GT(debug.getVertices().getVertexCount(), 0u);
    debug.clear();
    EXPECT_EQ(debug.getVertices().getVertexCount(), 0u);
}
