#include "hitbox/app/WholeFile.h"

#include "hitbox/app/Options.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace hitbox
{
namespace
{
namespace fs = std::filesystem;

SaveResult failed(const std::string& problem)
{
    return {false, problem};
}

// Hidden, beside the target, so the final rename stays within one folder (and never copies).
fs::path temporaryFor(const fs::path& target)
{
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    return folder / (".hitbox-" + target.filename().string().substr(0, 80) + ".writing");
}

} // namespace

SaveResult checkTextPath(const std::string& path)
{
    if (path.empty())
        return failed("no file name given");
    const fs::path target(path);
    std::error_code error;
    if (fs::is_symlink(fs::symlink_status(target, error)))
        return failed("it is a symbolic link (save to the file it points to, or to a new name)");
    const fs::file_status status = fs::status(target, error);
    if (fs::is_directory(status))
        return failed("it is a folder");
    if (fs::exists(status) && !fs::is_regular_file(status))
        return failed("it is not a regular file (a device or a pipe)");
    if (fs::exists(status) && (status.permissions() & fs::perms::owner_write) == fs::perms::none)
        return failed("it is read-only (make it writable, or save to a new name)");
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

SaveResult saveWholeFile(const std::string& path, const std::string& text)
{
    const SaveResult usable = checkTextPath(path);
    if (!usable)
        return usable;
    const fs::path temporary = temporaryFor(fs::path(path));
    std::error_code error;
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.flush();
        if (!out)
        {
            fs::remove(temporary, error);
            return failed("the write did not complete (is the disk full?)");
        }
    }
    std::ifstream in(temporary, std::ios::binary);
    const std::string readBack((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    in.close();
    if (readBack != text)
    {
        fs::remove(temporary, error);
        return failed("the write did not complete (is the disk full?)");
    }
    fs::rename(temporary, fs::path(path), error);
    if (error)
    {
        fs::remove(temporary, error);
        return failed("could not rename the finished file into place");
    }
    return {true, ""};
}

} // namespace hitbox
