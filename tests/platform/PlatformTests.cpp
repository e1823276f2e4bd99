// The platform wrapper answers the same on every system: what a program reads from the
// environment, the local time, its own folder.
#include "hitbox/platform/Platform.h"

#include <gtest/gtest.h>

#include <ctime>
#include <filesystem>
#include <optional>
#include <string>

namespace
{
const std::string variable = "HITBOX_PLATFORM_TEST_VARIABLE";
}

TEST(Platform, AnUnsetVariableIsNothingAndASetOneIsItsValue)
{
    ASSERT_TRUE(hitbox::platform::unsetEnvironmentVariable(variable));
    EXPECT_EQ(hitbox::platform::environmentVariable(variable), std::nullopt);

    ASSERT_TRUE(hitbox::platform::setEnvironmentVariable(variable, "a value with spaces"));
    EXPECT_EQ(hitbox::platform::environmentVariable(variable), "a value with spaces");

    ASSERT_TRUE(hitbox::platform::unsetEnvironmentVariable(variable));
    EXPECT_EQ(hitbox::platform::environmentVariable(variable), std::nullopt);
}

TEST(Platform, ANameWithAnEqualsSignIsRefused)
{
    EXPECT_FALSE(hitbox::platform::setEnvironmentVariable("A=B", "value"));
    EXPECT_FALSE(hitbox::platform::setEnvironmentVariable("", "value"));
}

TEST(Platform, LocalTimeIsACalendarDate)
{
    // Noon on 2 January 2020 (UTC) is 2 or 3 January (or 1 January) in every time zone.
    const std::tm local = hitbox::platform::localTime(std::time_t{1577966400});
    EXPECT_EQ(local.tm_year, 120);
    EXPECT_EQ(local.tm_mon, 0);
    EXPECT_GE(local.tm_mday, 1);
    EXPECT_LE(local.tm_mday, 3);
}

TEST(Platform, TheProcessHasAnIdAndAFolder)
{
    EXPECT_GT(hitbox::platform::processId(), 0);
    const std::string folder = hitbox::platform::programFolder();
    EXPECT_TRUE(std::filesystem::is_directory(folder)) << folder;
}

TEST(Platform, AMissingLibraryIsNull)
{
    const auto library = hitbox::platform::loadLibrary("libHitboxNoSuchLibrary.so.1");
    EXPECT_EQ(library, nullptr);
    EXPECT_EQ(hitbox::platform::findSymbol(library, "anything"), nullptr);
}

TEST(Platform, AVariableSetToNothingIsSetAndEmpty)
{
    ASSERT_TRUE(hitbox::platform::setEnvironmentVariable(variable, ""));
    EXPECT_EQ(hitbox::platform::environmentVariable(variable), "");
    EXPECT_TRUE(hitbox::platform::unsetEnvironmentVariable(variable));
}
