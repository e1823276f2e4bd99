#include "hitbox/app/WholeFile.h"

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

} // namespace

SaveResult saveWholeFile(const std::string& path, const std::string& text)
{
    const SaveResult usable = checkSavePath(path);
    if (!usable)
        return usable;
    const fs::path temporary = temporaryBeside(fs::path(path));
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
