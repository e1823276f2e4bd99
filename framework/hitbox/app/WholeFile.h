// WholeFile.h - save a text file (a replay, a timeline) so that it is either all there or
// not there at all: the same rule as Screenshot.h's pictures, for files of text.
#pragma once

#include "hitbox/app/Screenshot.h"

#include <string>

namespace hitbox
{

// Whether `path` can take a new file, checked before a run starts (so a bad name is reported
// before minutes of simulation, not after): the folder exists and takes a new file, and the
// name is not a folder, a device, a pipe, a symbolic link or a read-only file.
[[nodiscard]] SaveResult checkTextPath(const std::string& path);

// Writes `text` to a hidden temporary file beside `path`, reads it back, and only then renames
// it to `path`: an existing file is replaced only by a complete new one.
[[nodiscard]] SaveResult saveWholeFile(const std::string& path, const std::string& text);

} // namespace hitbox
