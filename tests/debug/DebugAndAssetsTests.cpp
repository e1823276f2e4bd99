// The debug renderer builds its lines without a window; assets are found or named.
#include "support/SfmlPrinters.h"

#include "hitbox/app/Assets.h"
#include "hitbox/debug/BroadphaseDrawing.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/objects/GameObject.h"
#include "hitbox/platform/Platform.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

TEST(DebugRenderer, TouchingObjectsUseTheTouchingColourAndShowVelocity)
{
    GameObject object;
    object.setSize({10.f, 10.f});
    object.setVelocity(100.f, 0.f);
    hitbox::DebugRenderer debug;
    debug.objectBox(object, true);
    const sf::VertexArray& lines = debug.getVertices();
    EXPECT_EQ(lines[0].color, hitbox::DebugRenderer::touchingColor);
    // After the 4 box edges: the velocity arrow's shaft, from the centre, a quarter second
    // long; it is a 2-pixel quad around the line from (5, 5) to (30, 5).
    const sf::Vertex& shaftStart = lines[24];
    const sf::Vertex& shaftEnd = lines[26];
    EXPECT_EQ(shaftStart.position, sf::Vector2f(5.f, 4.f));
    EXPECT_EQ(shaftEnd.position, sf::Vector2f(30.f, 6.f));
    EXPECT_EQ(shaftStart.color, hitbox::DebugRenderer::velocityColor);
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

TEST(Assets, TheFontIsFoundFromAnyFolder)
{
    EXPECT_NO_THROW(hitbox::findAsset("fonts/DejaVuSans.ttf"));
    EXPECT_NO_THROW(hitbox::loadFont());
}

TEST(Assets, AMissingAssetNamesThePathAndTheFix)
{
    try
    {
        hitbox::findAsset("fonts/NoSuchFont.ttf");
        FAIL() << "expected an AssetError";
    }
    catch (const hitbox::AssetError& error)
    {
        const std::string message = error.what();
        EXPECT_NE(message.find("assets/fonts/NoSuchFont.ttf"), std::string::npos) << message;
        EXPECT_NE(message.find("Fix:"), std::string::npos) << message;
    }
}

TEST(Assets, ADamagedFontIsReportedNotCrashed)
{
    const std::string folder = ::testing::TempDir() + "hitbox-bad-assets";
    std::filesystem::create_directories(folder + "/fonts");
    std::ofstream(folder + "/fonts/Broken.ttf") << "this is not a font";
    ASSERT_TRUE(hitbox::platform::setEnvironmentVariable("HITBOX_ASSETS", folder));
    try
    {
        hitbox::loadFont("fonts/Broken.ttf");
        FAIL() << "expected an AssetError";
    }
    catch (const hitbox::AssetError& error)
    {
        EXPECT_NE(std::string(error.what()).find("Broken.ttf"), std::string::npos);
    }
    hitbox::platform::unsetEnvironmentVariable("HITBOX_ASSETS");
}
