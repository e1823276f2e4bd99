// Assets.h - find the files in assets/ from any working directory, or say clearly why not.
//
// Search order: the folder in the HITBOX_ASSETS environment variable, the assets/ folder
// of the source tree this program was built from, an assets/ folder beside the program
// (or one level up), and ./assets. A missing or damaged file throws AssetError with one
// line naming the path and the fix; hitbox::App prints it and exits with code 1.
#pragma once

#include <SFML/Graphics/Font.hpp>

#include <memory>
#include <stdexcept>
#include <string>

namespace hitbox
{

class AssetError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

// The full path of an asset such as "fonts/DejaVuSans.ttf". Throws AssetError if absent.
[[nodiscard]] std::string findAsset(const std::string& relativePath);

// The font every Hitbox program uses for text, loaded from assets/fonts/.
[[nodiscard]] sf::Font loadFont(const std::string& relativePath = "fonts/DejaVuSans.ttf");

// A level's font, read from disk by the first get(): a level holds one and is still built
// (and tested) without the font file, because only drawing asks for it. Copies share it.
class LazyFont
{
public:
    // Loads the font on the first call (throws AssetError if it is missing), then returns it.
    [[nodiscard]] const sf::Font& get() const;

private:
    // Filled by the first get(): `mutable` so that a const render() may load it.
    mutable std::shared_ptr<const sf::Font> font;
};

} // namespace hitbox
