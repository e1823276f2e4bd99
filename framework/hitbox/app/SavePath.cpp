#include "hitbox/app/SavePath.h"

#include "hitbox/app/Options.h"

#include <cstdio>
#include <fstream>
#include <functional>
#include <system_error>

namespace hitbox
{
namespace fs = std::filesystem;

fs::path temporaryBeside(const fs::path& target)
{
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    char hash[24] = {};
    std::snprintf(
        hash, sizeof(hash), "%016llx",
        static_cast<unsigned long long>(std::hash<std::string>{}(target.filename().string())));
    return folder / (".hitbox-" + std::string(hash) + ".writing" + target.extension().string());
}

SaveResult checkSavePath(const std::string& path)
{
    if (path.empty())
        return SaveResult{false, "no file name given"};
    const fs::path target(path);
    std::error_code error;
    if (fs::is_symlink(fs::symlink_status(target, error)))
        return SaveResult{
            false, "it is a symbolic link (save to the file it points to, or to a new name)"};
    const fs::file_status status = fs::status(target, error);
    if (fs::is_directory(status))
        return SaveResult{false, "it is a folder"};
    if (fs::exists(status) && !fs::is_regular_file(status))
        return SaveResult{false, "it is not a regular file (a device or a pipe)"};
    // Someone made it read-only to keep it: replacing it (even as root, who may) is not ours.
    if (fs::exists(status) && (status.permissions() & fs::perms::owner_write) == fs::perms::none)
        return SaveResult{false, "it is read-only (make it writable, or save to a new name)"};
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, error))
        return SaveResult{false,
                          "the folder '" + printable(folder.string(), 200) + "' does not exist"};
    const fs::path temporary = temporaryBeside(target);
    const bool created = static_cast<bool>(std::ofstream(temporary, std::ios::binary));
    fs::remove(temporary, error);
    if (!created)
        return SaveResult{false, "cannot create a file in '" + printable(folder.string(), 200) +
                                     "' (is it writable?)"};
    return {true, ""};
}

} // namespace hitbox
