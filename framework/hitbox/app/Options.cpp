#include "hitbox/app/Options.h"

#include "hitbox/app/App.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

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

std::string shortNumber(double value)
{
    std::string text = std::to_string(value); // "0.500000"
    text.erase(text.find_last_not_of('0') + 1);
    if (!text.empty() && text.back() == '.')
        text.pop_back();
    return text;
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
    if (found == extra.end())
        return fallback;
    const std::string& text = found->second;
    char* end = nullptr;
    const double value = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    const bool allRead = !text.empty() && end == text.c_str() + text.size() &&
                         text.front() != ' ' && text.front() != '\t';
    if (!allRead || !std::isfinite(value) || value < lowest || value > highest)
        throw badValue(name, "a number from " + shortNumber(lowest) + " to " + shortNumber(highest),
                       text);
    return value;
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

Options parseOptions(int argc, const char* const argv[], const ProgramInfo& info)
{
    const long long framesPerSecond = static_cast<long long>(stepsPerSecond);
    Options options;
    for (int i = 1; i < argc; ++i)
    {
        const std::string option = argv[i];
        auto value = [&]() -> std::string
        {
            if (i + 1 >= argc)
                throw std::invalid_argument(printable(option) + " needs a value");
            return argv[++i];
        };
        if (option == "--headless")
            options.headless = true;
        else if (option == "--debug")
            options.debugBoxes = true;
        else if (option == "--frames")
            options.frames = toWholeNumber(option, value(), 0, maxSeconds * framesPerSecond);
        else if (option == "--seconds")
            options.frames = toWholeNumber(option, value(), 0, maxSeconds) * framesPerSecond;
        else if (option == "--screenshot")
        {
            options.screenshotPath = value();
            if (options.screenshotPath.empty())
                throw std::invalid_argument("--screenshot needs a file name, e.g. shot.png");
        }
        else if (option == "--seed")
            options.seed = static_cast<unsigned>(toWholeNumber(option, value(), 0, 4294967295));
        else
        {
            bool known = false;
            for (const std::string& extraOption : info.extraOptions)
                known = known || extraOption == option;
            if (!known)
            {
                std::string usage = "--headless --frames N --seconds S --screenshot FILE.png "
                                    "--debug --seed N";
                for (const std::string& extraOption : info.extraOptions)
                    usage += " " + extraOption + " VALUE";
                throw std::invalid_argument("unknown option '" + printable(option) +
                                            "' (the options are: " + usage + ")");
            }
            options.extra[option] = value();
        }
    }
    if (options.headless && !options.screenshotPath.empty())
        throw std::invalid_argument("--screenshot draws a picture, so it cannot be --headless");
    return options;
}

} // namespace hitbox
