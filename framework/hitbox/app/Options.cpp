#include "hitbox/app/Options.h"

#include "hitbox/app/Keys.h"
#include "hitbox/app/Loop.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace hitbox
{
namespace
{

// The one message format: "--balls needs a whole number from 1 to 20000, not 'abc'".
std::invalid_argument badValue(const std::string& name, const std::string& wanted,
                               const std::string& text)
{
    return std::invalid_argument(name + " needs " + wanted + ", not '" + printable(text) + "'");
}

long long toWholeNumber(const std::string& name, const std::string& text, long long lowest,
                        long long highest)
{
    long long value = 0;
    const char* end = text.data() + text.size();
    // from_chars: no locale, no leading blanks or '+', and out-of-range is reported, not UB.
    const std::from_chars_result result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end || value < lowest ||
        value > highest)
        throw badValue(name,
                       "a whole number from " + std::to_string(lowest) + " to " +
                           std::to_string(highest),
                       text);
    return value;
}

// The decimal form Options.h states: -?digits(.digits)?, nothing else (no exponent, hex,
// blanks, '+', "nan" or "inf", all of which strtod would read).
bool isPlainDecimal(const std::string& text)
{
    std::size_t i = text.size() > 0 && text[0] == '-' ? 1 : 0;
    auto digits = [&]
    {
        const std::size_t first = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9')
            ++i;
        return i > first;
    };
    if (!digits())
        return false;
    if (i < text.size() && text[i] == '.')
    {
        ++i;
        if (!digits())
            return false;
    }
    return i == text.size();
}

double toNumber(const std::string& name, const std::string& text, double lowest, double highest);

std::string shortNumber(double value)
{
    std::string text = std::to_string(value); // "0.500000"
    text.erase(text.find_last_not_of('0') + 1);
    if (!text.empty() && text.back() == '.')
        text.pop_back();
    return text;
}

double toNumber(const std::string& name, const std::string& text, double lowest, double highest)
{
    // strtod only after the form is checked; Hitbox never calls setlocale, so '.' is the point.
    const double value = isPlainDecimal(text) ? std::strtod(text.c_str(), nullptr) : 0.0;
    if (!isPlainDecimal(text) || !std::isfinite(value) || value < lowest || value > highest)
        throw badValue(name, "a number from " + shortNumber(lowest) + " to " + shortNumber(highest),
                       text);
    return value;
}

} // namespace

std::string printable(const std::string& text, std::size_t longest)
{
    std::string shown;
    for (std::size_t i = 0; i < text.size() && i < longest; ++i)
    {
        const unsigned char byte = static_cast<unsigned char>(text[i]);
        if (byte == '\r')
            shown += "\\r";
        else if (byte == '\n')
            shown += "\\n";
        else if (byte == '\t')
            shown += "\\t";
        else if (byte == '\0')
            shown += "\\0";
        else if (byte == '\\')
            shown += "\\\\";
        else if (byte < 0x20 || byte >= 0x7f)
        {
            const char* hex = "0123456789ABCDEF";
            shown += "\\x";
            shown += hex[byte / 16];
            shown += hex[byte % 16];
        }
        else
            shown += static_cast<char>(byte);
    }
    if (text.size() > longest)
        shown += "...";
    return shown;
}

std::string Options::get(const std::string& name, const std::string& fallback) const
{
    const auto found = extra.find(name);
    return found == extra.end() ? fallback : found->second;
}

long long Options::wholeNumber(const std::string& name, long long fallback, long long lowest,
                               long long highest) const
{
    const auto found = extra.find(name);
    return found == extra.end() ? fallback : toWholeNumber(name, found->second, lowest, highest);
}

double Options::number(const std::string& name, double fallback, double lowest,
                       double highest) const
{
    const auto found = extra.find(name);
    return found == extra.end() ? fallback : toNumber(name, found->second, lowest, highest);
}

bool Options::onOff(const std::string& name, bool fallback) const
{
    const auto found = extra.find(name);
    if (found == extra.end())
        return fallback;
    const std::string& text = found->second;
    if (text != "on" && text != "off")
        throw badValue(name, "on or off", text);
    return text == "on";
}

std::string Options::oneOf(const std::string& name, const std::string& fallback,
                           const std::vector<std::string>& choices) const
{
    const auto found = extra.find(name);
    if (found == extra.end())
        return fallback;
    const std::string& text = found->second;
    std::string list;
    for (const std::string& choice : choices)
    {
        if (choice == text)
            return text;
        list += (list.empty() ? "" : ", ") + choice;
    }
    throw badValue(name, "one of " + list, text);
}

std::string usagePage(const ProgramInfo& info)
{
    std::string page = info.title + "\n\nOptions every Hitbox program takes:\n";
    page += "  --headless          simulate with no window, then print one line of final state\n";
    page += "  --frames N          run N fixed steps (" +
            std::to_string(static_cast<int>(stepsPerSecond)) + " a second; headless default " +
            std::to_string(headlessDefaultSteps) + ")\n";
    page += "  --seconds S         the same in simulated seconds, e.g. 0.5 (0 to " +
            std::to_string(maxSeconds) + ")\n";
    page += "  --screenshot F.png  draw one frame into F.png after --frames steps\n";
    page += "  --debug             start with the debug boxes shown\n";
    page += "  --seed N            seed for anything random (0 to 4294967295)\n";
    page += "  --record FILE       write the seed, options and every step's input to FILE\n";
    page += "  --replay FILE       run FILE's recording again, exactly (its seed and options)\n";
    page +=
        "  --timeline F.csv    write every contact event (step, time, a, b, kind, normal, depth)\n";
    page += "  --pause-at-step N   in the window: pause after N steps (a replay: at its end)\n";
    page += "  --help, -h          print this page\n";
    if (!info.extraOptions.empty())
    {
        page += "\nThis program's own options (each takes a value):\n";
        for (const std::string& extraOption : info.extraOptions)
            page += "  " + extraOption + " VALUE\n";
    }
    page += "\nKeys in the window: " + sharedKeysHelp() + "\n";
    page += "A bad value gets one line on stderr and exit code 2.\n";
    return page;
}

Options parseOptions(int argc, const char* const argv[], const ProgramInfo& info)
{
    Options options;
    for (int i = 1; i < argc; ++i)
    {
        const std::string option = argv[i];
        if (option == "--help" || option == "-h")
        {
            options.help = true;
            return options;
        }
    }
    std::vector<std::string> given;
    for (int i = 1; i < argc; ++i)
    {
        const std::string option = argv[i];
        auto value = [&]() -> std::string
        {
            if (i + 1 >= argc)
                throw std::invalid_argument(printable(option) + " needs a value");
            return argv[++i];
        };
        const bool isShared = option == "--headless" || option == "--debug" ||
                              option == "--frames" || option == "--seconds" ||
                              option == "--screenshot" || option == "--seed" ||
                              option == "--record" || option == "--replay" ||
                              option == "--timeline" || option == "--pause-at-step";
        bool known = isShared;
        for (const std::string& extraOption : info.extraOptions)
            known = known || extraOption == option;
        if (!known)
        {
            std::string usage = "--headless --frames N --seconds S --screenshot FILE.png "
                                "--debug --seed N --record FILE --replay FILE --timeline F.csv "
                                "--pause-at-step N";
            for (const std::string& extraOption : info.extraOptions)
                usage += " " + extraOption + " VALUE";
            throw std::invalid_argument("unknown option '" + printable(option) +
                                        "' (the options are: " + usage + "; --help explains)");
        }
        for (const std::string& earlier : given)
        {
            if (earlier == option)
                throw std::invalid_argument(option + " is given twice; give it once");
            if ((earlier == "--frames" && option == "--seconds") ||
                (earlier == "--seconds" && option == "--frames"))
                throw std::invalid_argument(
                    "--frames and --seconds both set how long to run; give one of them");
        }
        given.push_back(option);

        if (option == "--headless")
            options.headless = true;
        else if (option == "--debug")
            options.debugBoxes = true;
        else if (option == "--frames")
            options.frames = toWholeNumber(option, value(), 0, maxSteps);
        else if (option == "--seconds")
            // Rounded to the nearest whole step: 0.5 s is 60 steps.
            options.frames =
                std::llround(toNumber(option, value(), 0.0, static_cast<double>(maxSeconds)) *
                             static_cast<double>(stepsPerSecond));
        else if (option == "--screenshot")
        {
            options.screenshotPath = value();
            if (options.screenshotPath.empty())
                throw std::invalid_argument("--screenshot needs a file name, e.g. shot.png");
        }
        else if (option == "--seed")
            options.seed = static_cast<unsigned>(toWholeNumber(option, value(), 0, 4294967295));
        else if (option == "--record" || option == "--replay" || option == "--timeline")
        {
            std::string& path = option == "--record"   ? options.recordPath
                                : option == "--replay" ? options.replayPath
                                                       : options.timelinePath;
            path = value();
            if (path.empty())
                throw std::invalid_argument(option + " needs a file name, e.g. run.csv");
        }
        else if (option == "--pause-at-step")
            options.pauseAtStep = toWholeNumber(option, value(), 0, maxSteps);
        else
            options.extra[option] = value();
    }
    if (options.headless && !options.screenshotPath.empty())
        throw std::invalid_argument("--screenshot draws a picture, so it cannot be --headless");
    if (!options.recordPath.empty() && !options.replayPath.empty())
        throw std::invalid_argument("--record and --replay: give one of them");
    if (options.pauseAtStep >= 0 && (options.headless || !options.screenshotPath.empty()))
        throw std::invalid_argument("--pause-at-step pauses the window, so it needs one "
                                    "(not --headless or --screenshot)");
    return options;
}

} // namespace hitbox
