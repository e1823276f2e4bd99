// Screenshot.h - save a picture so that it is either all there or not there at all.
//
// The picture goes to a hidden temporary file in the same folder, is read back and compared
// with what was meant to be written, and only then renamed to its name: a full disk, a
// folder that cannot be written or a cut-off write leaves nothing behind, and the caller
// says "saved" only for a file that is complete.
#pragma once

#include "hitbox/app/SavePath.h"

#include <SFML/Graphics/Image.hpp>

#include <string>

namespace hitbox
{

// Whether `path` can take a picture, checked without drawing: SavePath.h's checkSavePath (the
// folder takes a new file; not a folder, a device, a pipe, a symbolic link or a read-only
// file), then the name ends in .png/.bmp/.tga/.jpg. Used before a long --screenshot
// simulation, and by saveImage.
[[nodiscard]] SaveResult checkImagePath(const std::string& path);

// Saves `image` as `path` (.png, .bmp, .tga or .jpg, chosen by the ending). An existing
// file of that name is replaced only by a complete new one; what checkImagePath refuses never is.
[[nodiscard]] SaveResult saveImage(const sf::Image& image, const std::string& path);

// A name in `folder` for an F12 screenshot that no file has yet: screenshot-STAMP.png, then
// screenshot-STAMP-2.png, -3, ... so presses within the same second each get their own file.
// `stamp` is usually screenshotStamp().
[[nodiscard]] std::string freeScreenshotName(const std::string& folder, const std::string& stamp);

// The local date and time as YYYYMMDD-HHMMSS.
[[nodiscard]] std::string screenshotStamp();

} // namespace hitbox
