#include "hitbox/app/Screenshot.h"

#include "hitbox/app/Options.h"
#include "hitbox/platform/Platform.h"

#include <SFML/System/Err.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
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

// Hidden, beside the target (a rename within one folder never copies), with the same ending.
// Named by a hash of the file name, not the name itself: a legal 254-byte name plus
// ".writing" would be longer than a file system allows (255 bytes on most).
fs::path temporaryFor(const fs::path& target)
{
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    char hash[24] = {};
    std::snprintf(
        hash, sizeof(hash), "%016llx",
        static_cast<unsigned long long>(std::hash<std::string>{}(target.filename().string())));
    return folder / (".hitbox-" + std::string(hash) + ".writing" + target.extension().string());
}

SaveResult checkImagePath(const std::string& path)
{
    if (path.empty())
        return failed("no file name given");
    const fs::path target(path);
    std::error_code error;
    const fs::file_status link = fs::symlink_status(target, error);
    if (fs::is_symlink(link))
        return failed("it is a symbolic link (save to the file it points to, or to a new name)");
    const fs::file_status status = fs::status(target, error);
    if (fs::is_directory(status))
        return failed("it is a folder");
    if (fs::exists(status) && !fs::is_regular_file(status))
        return failed("it is not a regular file (a device or a pipe)");
    // Someone made it read-only to keep it: replacing it (even as root, who may) is not ours.
    if (fs::exists(status) && (status.permissions() & fs::perms::owner_write) == fs::perms::none)
        return failed("it is read-only (make it writable, or save to a new name)");
    const std::string ending = lowerCase(target.extension().string());
    if (ending != ".png" && ending != ".bmp" && ending != ".tga" && ending != ".jpg" &&
        ending != ".jpeg")
        return failed("the name must end in .png (or .bmp, .tga, .jpg)");

    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, error))
        return failed("the folder '" + printable(folder.string(), 200) + "' does not exist");
    const fs::path temporary = temporaryFor(target);
    const bool created = static_cast<bool>(std::ofstream(temporary, std::ios::binary));
    fs::remove(temporary, error);
    if (!created)
        return failed("cannot create a file in '" + printable(folder.string(), 200) +
                      "' (is it writable?)");
    return {true, ""};
}

SaveResult saveImage(const sf::Image& image, const std::string& path)
{
    const SaveResult usable = checkImagePath(path);
    if (!usable)
        return usable;
    const fs::path target(path);
    const std::string ending = lowerCase(target.extension().string());
    const fs::path temporary = temporaryFor(target);
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
