// The command line's typed getters (issue 19): one message format, stated ranges, no
// overflow, nothing silently read as something else.
#include "support/CommandLine.h"

#include "hitbox/app/Loop.h"
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

// The limits come from their one home (Options.h: maxSeconds, maxSteps; Loop.h: the step rate).
TEST(OptionsShared, SecondsAndFramesHaveAStatedMaximumAndNeverOverflow)
{
    const std::string mostSeconds = std::to_string(hitbox::maxSeconds);
    const std::string mostSteps = std::to_string(hitbox::maxSteps);
    EXPECT_EQ(hitbox::maxSteps,
              hitbox::maxSeconds * static_cast<long long>(hitbox::stepsPerSecond));
    EXPECT_EQ(parseCommandLine({"--seconds", mostSeconds.c_str()}).frames, hitbox::maxSteps);
    EXPECT_EQ(messageOf(
                  [] {
                      parseCommandLine({"--seconds", "76861433640456466"});
                  }),
              "--seconds needs a number from 0 to " + mostSeconds + ", not '76861433640456466'");
    const std::string tooMany = std::to_string(hitbox::maxSteps + 1);
    EXPECT_EQ(messageOf(
                  [&] {
                      parseCommandLine({"--frames", tooMany.c_str()});
                  }),
              "--frames needs a whole number from 0 to " + mostSteps + ", not '" + tooMany + "'");
}

// Items 22 and 24: --help anywhere, half seconds, and no option silently overriding another.
TEST(OptionsShared, HelpHalfSecondsAndConflicts)
{
    EXPECT_TRUE(parseCommandLine({"--frames", "bogus", "-h"}).help);
    EXPECT_EQ(parseCommandLine({"--seconds", "0.5"}).frames,
              static_cast<long long>(hitbox::stepsPerSecond / 2.f));
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

// The help page states the step rate and the headless default from their constants, so it
// cannot go stale when either changes.
TEST(OptionsShared, HelpStatesTheStepRateAndTheHeadlessDefault)
{
    const std::string page = hitbox::usagePage({"Test"});
    const std::string frames = "--frames N          run N fixed steps (" +
                               std::to_string(static_cast<int>(hitbox::stepsPerSecond)) +
                               " a second; headless default " +
                               std::to_string(hitbox::headlessDefaultSteps) + ")\n";
    EXPECT_NE(page.find(frames), std::string::npos) << page;
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
