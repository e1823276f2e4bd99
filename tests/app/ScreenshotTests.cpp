// Screenshots are all there or not there (issue 19): no "saved" for a file that was not,
// no half-written file under the final name, no temporary left behind.
#include "hitbox/app/Screenshot.h"

#include "hitbox/platform/Platform.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/Image.hpp>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
// A fresh empty folder for one test, named by process and a random number so that another
// user's (or another run's) leftovers in the shared temporary folder never get in the way.
fs::path emptyFolder(const std::string& name)
{
    static const unsigned runNumber = std::random_device{}();
    const fs::path folder = fs::temp_directory_path() /
                            ("hitbox-screenshot-" + std::to_string(hitbox::platform::processId()) +
                             "-" + std::to_string(runNumber) + "-" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

sf::Image noisyImage()
{
    // Noise does not compress: the PNG is far bigger than the file-size limit used below.
    const unsigned size = 256;
    std::vector<std::uint8_t> pixels; // red, green, blue, alpha for each pixel, row by row
    unsigned value = 12345;
    for (unsigned pixel = 0; pixel < size * size; ++pixel)
    {
        value = value * 1103515245u + 12345u;
        pixels.insert(pixels.end(), {static_cast<std::uint8_t>(value >> 24),
                                     static_cast<std::uint8_t>(value >> 16),
                                     static_cast<std::uint8_t>(value >> 8), 255});
    }
    return hitbox::makeImage(size, size, pixels.data());
}

std::size_t filesIn(const fs::path& folder)
{
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
        ++count;
    return count;
}
} // namespace

TEST(Screenshot, AGoodSaveLeavesExactlyTheFileAndItDecodes)
{
    const fs::path folder = emptyFolder("good");
    const std::string path = (folder / "shot.png").string();
    const sf::Image image = noisyImage();
    EXPECT_TRUE(hitbox::saveImage(image, path));
    sf::Image readBack;
    ASSERT_TRUE(readBack.loadFromFile(path));
    EXPECT_EQ(readBack.getSize(), image.getSize());
    EXPECT_EQ(filesIn(folder), 1u);
}

TEST(Screenshot, AFolderADeviceAndAMissingFolderAreRefusedAndLeaveNothing)
{
    const fs::path folder = emptyFolder("refused");
    fs::create_directory(folder / "taken.png");
    const hitbox::SaveResult onFolder =
        hitbox::saveImage(noisyImage(), (folder / "taken.png").string());
    EXPECT_FALSE(onFolder);
    EXPECT_EQ(onFolder.problem, "it is a folder");
    EXPECT_EQ(filesIn(folder), 1u); // no NAME.partial.png or other leftover

    const hitbox::SaveResult noFolder =
        hitbox::saveImage(noisyImage(), (folder / "missing" / "a.png").string());
    EXPECT_FALSE(noFolder);
    EXPECT_NE(noFolder.problem.find("does not exist"), std::string::npos) << noFolder.problem;
    EXPECT_EQ(hitbox::saveImage(noisyImage(), (folder / "shot.txt").string()).problem,
              "the name must end in .png (or .bmp, .tga, .jpg)");
    // The file's own state is told before its ending: `--screenshot shots` names a folder.
    fs::create_directory(folder / "shots");
    EXPECT_EQ(hitbox::checkImagePath((folder / "shots").string()).problem, "it is a folder");
    // A pipe stands for any device: never a real one such as /dev/full, which a broken
    // save run as root would replace. Windows has no named pipes in folders.
    const fs::path pipe = folder / "pipe.png";
    if (hitbox::platform::makeNamedPipe(pipe.string()))
    {
        const hitbox::SaveResult onPipe = hitbox::saveImage(noisyImage(), pipe.string());
        EXPECT_FALSE(onPipe);
        EXPECT_EQ(onPipe.problem, "it is not a regular file (a device or a pipe)");
        EXPECT_EQ(fs::status(pipe).type(), fs::file_type::fifo);
    }
}

// A full disk, made without root: a file-size limit makes every write past 4 KiB fail, as a
// disk with 4 KiB free would. Skipped where there is no such limit (Windows).
TEST(Screenshot, AFullDiskIsReportedAndTheOldFileIsKept)
{
    const fs::path folder = emptyFolder("full");
    const std::string path = (folder / "shot.png").string();
    std::ofstream(path) << "the previous picture";

    hitbox::SaveResult result;
    if (!hitbox::platform::runWithFileSizeLimit(
            4096, [&] { result = hitbox::saveImage(noisyImage(), path); }))
        GTEST_SKIP() << "this system cannot limit a file's size";

    EXPECT_FALSE(result);
    EXPECT_EQ(result.problem, "the write did not complete (is the disk full?)");
    EXPECT_EQ(filesIn(folder), 1u); // the temporary is gone
    std::ifstream kept(path);
    std::string text;
    std::getline(kept, text);
    EXPECT_EQ(text, "the previous picture");
}

TEST(Screenshot, ThreePressesInOneSecondGiveThreeFiles)
{
    const fs::path folder = emptyFolder("presses");
    std::set<std::string> names;
    for (int press = 0; press < 3; ++press)
    {
        const std::string name = hitbox::freeScreenshotName(folder.string(), "20261123-200000");
        EXPECT_TRUE(hitbox::saveImage(noisyImage(), name)) << name;
        names.insert(name);
    }
    EXPECT_EQ(names.size(), 3u);
    EXPECT_EQ(filesIn(folder), 3u);
    EXPECT_TRUE(fs::exists(folder / "screenshot-20261123-200000-3.png"));
}
