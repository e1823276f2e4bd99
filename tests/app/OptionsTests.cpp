// The command line's typed getters (issue 19): one message format, stated ranges, no
// overflow, nothing silently read as something else.
#include "support/CommandLine.h"

#include "hitbox/app/Options.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace
{
// The message a bad command line throws, or "" when it parses.
template <typename Read>
std::string messageOf(Read read)
{
    try
    {
        read();
    }
    catch (const std::invalid_argument& error)
    {
        return error.what();
    }
    return "";
}
} // namespace

TEST(OptionsWholeNumber, ReadsDigitsWithinTheRangeAndTheFallbackWhenAbsent)
{
    EXPECT_EQ(parseCommandLine({"--balls", "12"}, {"--balls"}).wholeNumber("--balls", 2, 1, 100),
              12);
    EXPECT_EQ(parseCommandLine({"--balls", "-3"}, {"--balls"}).wholeNumber("--balls", 2, -5, 5),
              -3);
    EXPECT_EQ(parseCommandLine({}, {"--balls"}).wholeNumber("--balls", 2, 1, 100), 2);
}

TEST(OptionsWholeNumber, RefusesEverythingElseWithOneMessageFormat)
{
    const std::string wanted = "--balls needs a whole number from 1 to 100, not '";
    for (const char* bad :
         {"abc", "200000000", "-5", "1e9", "", " 5", "+5", "12abc", "0", "99999999999999999999999"})
    {
        const hitbox::Options options = parseCommandLine({"--balls", bad}, {"--balls"});
        EXPECT_EQ(messageOf([&] { EXPECT_EQ(options.wholeNumber("--balls", 2, 1, 100), 2); }),
                  wanted + bad + "'")
            << bad;
    }
}

TEST(OptionsNumber, ReadsDecimalsAndRefusesNanInfinityAndText)
{
    EXPECT_DOUBLE_EQ(parseCommandLine({"--t", "0.5"}, {"--t"}).number("--t", 0, 0, 10), 0.5);
    for (const char* bad : {"nan", "inf", "abc", "11", "-1", "1x", ""})
        EXPECT_EQ(
            messageOf(
                [&] {
                    EXPECT_EQ(parseCommandLine({"--t", bad}, {"--t"}).number("--t", 0, 0, 10), 0.0);
                }),
            std::string("--t needs a number from 0 to 10, not '") + bad + "'");
}

// Issue 25, item 23: Options.h says decimal; strtod alone also read hex, exponents and
// denormals ("0x10" was 16, "1e-400" was 0).
TEST(OptionsNumber, OnlyPlainDecimalsAreNumbers)
{
    EXPECT_DOUBLE_EQ(parseCommandLine({"--t", "-2.25"}, {"--t"}).number("--t", 0, -10, 10), -2.25);
    for (const char* bad : {"0x10", "0x1p3", "1e-400", "1e2", " 5", "+5", ".5", "5.", "1.2.3", "-"})
        EXPECT_EQ(messageOf(
                      [&] {
                          EXPECT_EQ(
                              parseCommandLine({"--t", bad}, {"--t"}).number("--t", 0, -10, 10),
                              0.0);
                      }),
                  std::string("--t needs a number from -10 to 10, not '") + bad + "'");
}

TEST(OptionsOnOff, OnlyOnAndOffAreAnswers)
{
    EXPECT_TRUE(parseCommandLine({"--demo", "on"}, {"--demo"}).onOff("--demo", false));
    EXPECT_FALSE(parseCommandLine({"--demo", "off"}, {"--demo"}).onOff("--demo", true));
    EXPECT_TRUE(parseCommandLine({}, {"--demo"}).onOff("--demo", true));
    for (const char* bad : {"no", "maybe", "1", "ON"})
        EXPECT_EQ(messageOf(
                      [&] {
                          EXPECT_FALSE(
                              parseCommandLine({"--demo", bad}, {"--demo"}).onOff("--demo", false));
                      }),
                  std::string("--demo needs on or off, not '") + bad + "'");
}

TEST(OptionsOneOf, SpelledExactlyOrAnError)
{
    const std::vector<std::string> modes = {"swept", "discrete"};
    EXPECT_EQ(parseCommandLine({"--mode", "discrete"}, {"--mode"}).oneOf("--mode", "swept", modes),
              "discrete");
    EXPECT_EQ(parseCommandLine({}, {"--mode"}).oneOf("--mode", "", modes), "");
    EXPECT_EQ(
        messageOf(
            [&] {
                EXPECT_EQ(
                    parseCommandLine({"--mode", "bogus"}, {"--mode"}).oneOf("--mode", "", modes),
                    "");
            }),
        "--mode needs one of swept, discrete, not 'bogus'");
}

TEST(OptionsShared, SecondsAndFramesHaveAStatedMaximumAndNeverOverflow)
{
    EXPECT_EQ(parseCommandLine({"--seconds", "100000000"}).frames, 12'000'000'000LL);
    EXPECT_EQ(messageOf(
                  [] {
                      parseCommandLine({"--seconds", "76861433640456466"});
                  }),
              "--seconds needs a number from 0 to 100000000, not '76861433640456466'");
    EXPECT_EQ(messageOf(
                  [] {
                      parseCommandLine({"--frames", "12000000001"});
                  }),
              "--frames needs a whole number from 0 to 12000000000, not '12000000001'");
}

// Items 22 and 24: --help anywhere, half seconds, and no option silently overriding another.
TEST(OptionsShared, HelpHalfSecondsAndConflicts)
{
    EXPECT_TRUE(parseCommandLine({"--frames", "bogus", "-h"}).help);
    EXPECT_EQ(parseCommandLine({"--seconds", "0.5"}).frames, 60);
    EXPECT_EQ(messageOf(
                  [] {
                      parseCommandLine({"--seed", "1", "--seed", "2"});
                  }),
              "--seed is given twice; give it once");
    EXPECT_EQ(messageOf(
                  [] {
                      parseCommandLine({"--seconds", "1", "--frames", "2"});
                  }),
              "--frames and --seconds both set how long to run; give one of them");
}

TEST(OptionsShared, SeedOutOfRangeIsAnErrorNotAnotherSeed)
{
    EXPECT_EQ(parseCommandLine({"--seed", "4294967295"}).seed, 4294967295u);
    EXPECT_EQ(messageOf(
                  [] {
                      parseCommandLine({"--seed", "4294967297"});
                  }),
              "--seed needs a whole number from 0 to 4294967295, not '4294967297'");
}

TEST(OptionsShared, EmptyScreenshotNameIsAUsageError)
{
    EXPECT_EQ(messageOf(
                  [] {
                      parseCommandLine({"--screenshot", ""});
                  }),
              "--screenshot needs a file name, e.g. shot.png");
}

TEST(OptionsPrintable, ControlBytesAreEscapedAndLongTextIsCut)
{
    EXPECT_EQ(hitbox::printable(std::string("a\r\0\xEF\xBB\xBF\\", 7)),
              "a\\r\\0\\xEF\\xBB\\xBF\\\\");
    EXPECT_EQ(hitbox::printable(std::string(100, 'x'), 5), "xxxxx...");
}

// A --screenshot picture is drawn for a document and compared run against run (the slides'
// figures): it must leave out timings. A window run (F12 saves it) and a headless run do not.
TEST(OptionsRepeatablePicture, OnlyAScreenshotRunAsksForOne)
{
    EXPECT_TRUE(
        parseCommandLine({"--screenshot", "shot.png", "--frames", "60"}, {}).repeatablePicture());
    EXPECT_FALSE(parseCommandLine({"--frames", "60"}, {}).repeatablePicture());
    EXPECT_FALSE(parseCommandLine({"--headless", "--frames", "60"}, {}).repeatablePicture());
}
