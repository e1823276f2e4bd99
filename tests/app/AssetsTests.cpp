// Assets: a picture or font is found from any folder the program runs in, or its absence is
// named with the fix; a damaged file is reported, never a crash.
#include "hitbox/app/Assets.h"
#include "hitbox/platform/Platform.h"

#include <SFML/Graphics/Font.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

TEST(Assets, TheFontIsFoundFromAnyFolder)
{
    EXPECT_NO_THROW(EXPECT_FALSE(hitbox::findAsset("fonts/DejaVuSans.ttf").empty()));
    EXPECT_NO_THROW([[maybe_unused]] const sf::Font font = hitbox::loadFont());
}

TEST(Assets, AMissingAssetNamesThePathAndTheFix)
{
    try
    {
        const std::string found = hitbox::findAsset("fonts/NoSuchFont.ttf");
        FAIL() << "expected an AssetError, found " << found;
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
        [[maybe_unused]] const sf::Font font = hitbox::loadFont("fonts/Broken.ttf");
        FAIL() << "expected an AssetError";
    }
    catch (const hitbox::AssetError& error)
    {
        EXPECT_NE(std::string(error.what()).find("Broken.ttf"), std::string::npos);
    }
    EXPECT_TRUE(hitbox::platform::unsetEnvironmentVariable("HITBOX_ASSETS"));
}
