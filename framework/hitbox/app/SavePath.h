// SavePath.h - the one rule for where a file may be saved, shared by pictures (Screenshot.h)
// and text (WholeFile.h): what may be replaced, and the hidden temporary file a save writes
// first so that a file is either all there or not there at all.
#pragma once

#include <filesystem>
#include <string>

namespace hitbox
{

struct SaveResult
{
    bool saved = false;
    std::string problem; // when not saved: why, in one line, e.g. "the disk is full"

    explicit operator bool() const { return saved; }
};

// Whether `path` can take a new file, checked without writing it: the folder exists and takes
// a new file, and the name is not empty, a folder, a device, a pipe, a symbolic link or a
// read-only file (those are never replaced). The first problem found, in that order, is the one
// reported.
[[nodiscard]] SaveResult checkSavePath(const std::string& path);

// The hidden file a save of `target` writes first: beside it (a rename within one folder never
// copies), with the same ending (so a picture's format is still chosen by it), named by a hash
// of the file name rather than the name itself (a legal 254-byte name plus ".writing" would be
// longer than most file systems allow, 255 bytes).
[[nodiscard]] std::filesystem::path temporaryBeside(const std::filesystem::path& target);

} // namespace hitbox
