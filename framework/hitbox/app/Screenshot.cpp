#include "hitbox/app/Screenshot.h"

#include "hitbox/platform/Platform.h"

#include <SFML/System/Err.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <system_error>

namespace hitbox
{
namespace
{
namespace fs = std::filesystem;

std::string lowerCase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// True when the file at `path` decodes to exactly `image` (for JPEG, which is lossy: to an
// image of the same size). A cut-off or empty file does not decode.
bool holdsImage(const std::string& path, const sf::Image& image, bool lossless)
{
    sf::Image readBack;
    if (!readBack.loadFromFile(path) || readBack.getSize() != image.getSize())
        return false;
    if (!lossless)
        return true;
    const std::size_t bytes = std::size_t{image.getSize().x} * image.getSize().y * 4;
    return bytes == 0 || std::memcmp(readBack.getPixelsPtr(), image.getPixelsPtr(), bytes) == 0;
}

SaveResult failed(const std::string& problem)
{
    return {false, problem};
}

} // namespace

SaveResult checkImagePath(const std::string& path)
{
    // The file's own state first: "it is a folder" tells more about `--screenshot shots/` than
    // a wrong ending would.
    const SaveResult usable = checkSavePath(path);
    if (!usable)
        return usable;
    const std::string ending = lowerCase(fs::path(path).extension().string());
    if (ending != ".png" && ending != ".bmp" && ending != ".tga" && ending != ".jpg" &&
        ending != ".jpeg")
        return failed("the name must end in .png (or .bmp, .tga, .jpg)");
    return {true, ""};
}

SaveResult saveImage(const sf::Image& image, const std::string& path)
{
    const SaveResult usable = checkImagePath(path);
    if (!usable)
        return usable;
    const fs::path target(path);
    const std::string ending = lowerCase(target.extension().string());
    const fs::path temporary = temporaryBeside(target);
    std::error_code error;

    // SFML prints its own lines on failure; the caller prints one clear line instead.
    std::ostringstream sfmlMessage;
    std::streambuf* previous = sf::err().rdbuf(sfmlMessage.rdbuf());
    const bool written =
        image.saveToFile(temporary.string()) &&
        holdsImage(temporary.string(), image, ending != ".jpg" && ending != ".jpeg");
    sf::err().rdbuf(previous);
    if (!written)
    {
        fs::remove(temporary, error);
        return failed("the write did not complete (is the disk full?)");
    }
    fs::rename(temporary, target, error);
    if (error)
    {
        fs::remove(temporary, error);
        return failed("could not rename the finished file into place");
    }
    return {true, ""};
}

std::string freeScreenshotName(const std::string& folder, const std::string& stamp)
{
    const fs::path base = fs::path(folder) / ("screenshot-" + stamp);
    std::string name = base.string() + ".png";
    std::error_code error;
    for (int count = 2; fs::exists(name, error); ++count)
        name = base.string() + "-" + std::to_string(count) + ".png";
    return name;
}

std::string screenshotStamp()
{
    char stamp[32] = {};
    const std::tm now = platform::localTime(std::time(nullptr));
    std::strftime(stamp, sizeof(stamp), "%Y%m%d-%H%M%S", &now);
    return stamp;
}

} // namespace hitbox
