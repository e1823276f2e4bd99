#include "hitbox/app/Assets.h"

#include "hitbox/app/Options.h"
#include "hitbox/platform/Platform.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/System/Err.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

namespace hitbox
{
namespace
{

// Exists at all: opening it here would block on a pipe, and an unreadable file is not missing.
bool fileExists(const std::string& path)
{
    std::error_code error;
    return std::filesystem::exists(path, error);
}

std::vector<std::string> assetFolders()
{
    std::vector<std::string> folders;
    if (const std::optional<std::string> fromEnvironment =
            platform::environmentVariable("HITBOX_ASSETS"))
        folders.push_back(*fromEnvironment);
#ifdef HITBOX_SOURCE_ASSETS_DIR
    folders.emplace_back(HITBOX_SOURCE_ASSETS_DIR);
#endif
    const std::string programFolder = platform::programFolder();
    folders.push_back(programFolder + "/assets");
    folders.push_back(programFolder + "/../assets");
    folders.emplace_back("assets");
    return folders;
}

} // namespace

std::string findAsset(const std::string& relativePath)
{
    std::string looked;
    for (const std::string& folder : assetFolders())
    {
        const std::string candidate = folder + "/" + relativePath;
        if (fileExists(candidate))
            return candidate;
        looked += (looked.empty() ? "" : ", ") + folder;
    }
    throw AssetError("missing asset 'assets/" + printable(relativePath, 200) + "' (looked in " +
                     printable(looked, 400) +
                     "). Fix: restore it with 'git checkout -- assets', or set HITBOX_ASSETS "
                     "to the folder that holds it.");
}

sf::Font loadFont(const std::string& relativePath)
{
    const std::string path = findAsset(relativePath);
    // Look before opening: opening a pipe waits forever for a writer, a device never ends.
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw AssetError("the font '" + printable(path, 200) +
                         "' is not a regular file (a folder, a device or a pipe). Fix: restore "
                         "it with 'git checkout -- assets/" +
                         printable(relativePath, 200) + "'.");
    sf::Font font;
    // SFML prints its own multi-line complaint; keep it and say one clear line instead.
    std::ostringstream sfmlMessage;
    std::streambuf* previous = sf::err().rdbuf(sfmlMessage.rdbuf());
    const bool loaded = openFont(font, path);
    sf::err().rdbuf(previous);
    if (!loaded)
        throw AssetError("the font '" + printable(path, 200) +
                         "' is damaged or not a font. Fix: restore it with 'git checkout -- "
                         "assets/" +
                         relativePath + "'.");
    return font;
}

const sf::Font& LazyFont::get() const
{
    if (!font)
        font = std::make_shared<const sf::Font>(loadFont());
    return *font;
}

} // namespace hitbox
