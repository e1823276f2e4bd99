// WholeFile.h - save a text file (a replay, a timeline) so that it is either all there or
// not there at all: SavePath.h's rule, as Screenshot.h uses it for pictures, for files of text.
#pragma once

#include "hitbox/app/SavePath.h"

#include <string>

namespace hitbox
{

// Writes `text` to a hidden temporary file beside `path`, reads it back, and only then renames
// it to `path`: an existing file is replaced only by a complete new one; what checkSavePath
// refuses never is (call that before a long run, so a bad name is reported before minutes of
// simulation, not after).
[[nodiscard]] SaveResult saveWholeFile(const std::string& path, const std::string& text);

} // namespace hitbox
