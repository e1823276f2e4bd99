#include "hitbox/app/private/ScreenshotRun.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Letterbox.h"
#include "hitbox/app/Screenshot.h"
#include "hitbox/app/private/Frame.h"
#include "hitbox/app/private/LongRun.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RenderTexture.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <SFML/System/Err.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>

namespace hitbox
{

int saveScreenshot(Level& level, const Options& options, const ProgramInfo& info)
{
    const std::string shownPath = printable(options.screenshotPath, 200);
    // A bad name is reported before a long simulation, not after it.
    const SaveResult writable = checkImagePath(options.screenshotPath);
    if (!writable)
    {
        std::cerr << info.title << ": could not save '" << shownPath << "': " << writable.problem
                  << std::endl;
        return 1;
    }
    const sf::Font font = loadFont();
    if (!simulateReporting(level, options.frames >= 0 ? options.frames : 0, info.title))
        return stoppedExitCode;

    // The whole world in one picture, shrunk to what the graphics driver can hold.
    const sf::Vector2f world = level.getWorldSize();
    const unsigned largest = std::min(sf::Texture::getMaximumSize(), maxPictureSide);
    const sf::Vector2u size = fitInside(world, {largest, largest});
    sf::RenderTexture canvas;
    std::ostringstream sfmlMessage; // SFML's own reason, told in our one line
    std::streambuf* previous = sf::err().rdbuf(sfmlMessage.rdbuf());
    const bool made = makeCanvas(canvas, size.x, size.y);
    sf::err().rdbuf(previous);
    if (!made)
    {
        std::string reason = sfmlMessage.str();
        while (!reason.empty() && (reason.back() == '\n' || reason.back() == '\r'))
            reason.pop_back();
        std::cerr << info.title << ": could not create a " << size.x << " x " << size.y
                  << " pixel picture to draw into (the graphics driver said: "
                  << printable(reason.empty() ? "nothing" : reason, 200) << ")" << std::endl;
        return 1;
    }
    FrameSettings settings;
    settings.showDebug = options.debugBoxes;
    canvas.setView(sf::View(sf::FloatRect({0.f, 0.f}, world)));
    drawFrame(canvas, level, font, settings, 1.f);
    canvas.display();
    const SaveResult saved = saveImage(canvas.getTexture().copyToImage(), options.screenshotPath);
    if (!saved)
    {
        std::cerr << info.title << ": could not save '" << shownPath << "': " << saved.problem
                  << std::endl;
        return 1;
    }
    std::cout << info.title << ": saved " << shownPath << std::endl;
    return 0;
}

void saveWindowPicture(const sf::RenderWindow& window)
{
    const std::string path = freeScreenshotName("", screenshotStamp());
    const SaveResult saved = saveImage(captureWindow(window), path);
    if (saved)
        std::cout << "Saved " << path << std::endl;
    else
        std::cerr << "Could not save " << path << ": " << saved.problem << std::endl;
}

} // namespace hitbox
