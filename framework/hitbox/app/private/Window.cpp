#include "hitbox/app/private/Window.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/FixedStep.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Screenshot.h"
#include "hitbox/debug/DebugRenderer.h"

#include <SFML/Graphics.hpp>

#include <iostream>
#include <string>

namespace hitbox
{
namespace
{

const char* sharedKeys = "F1 debug boxes   P pause   N step   F12 screenshot   Esc quit";

struct FrameSettings
{
    bool showDebug = false;
    bool paused = false;
    int framesPerSecond = 0;
};

std::string helpLine(const Level& level, const FrameSettings& settings)
{
    std::string line = sharedKeys;
    const std::string levelKeys = level.getHelpText();
    if (!levelKeys.empty())
        line += "   |   " + levelKeys;
    if (settings.framesPerSecond > 0)
        line += "   |   " + std::to_string(settings.framesPerSecond) + " fps";
    return line;
}

// Scene, then debug shapes, then the help line: the same picture in the window and in a
// --screenshot file.
void drawFrame(sf::RenderTarget& target, const Level& level, const sf::Font& font,
               const FrameSettings& settings)
{
    const sf::Vector2f world = level.getWorldSize();
    target.clear(sf::Color(18, 20, 28));
    level.render(target);
    if (settings.showDebug)
    {
        DebugRenderer debug;
        level.renderDebug(debug);
        debug.draw(target);
    }

    const float barHeight = 24.f;
    sf::RectangleShape bar({world.x, barHeight});
    bar.setPosition(0.f, world.y - barHeight);
    bar.setFillColor(sf::Color(0, 0, 0, 170));
    target.draw(bar);
    sf::Text help(helpLine(level, settings), font, 14);
    help.setFillColor(sf::Color(220, 220, 220));
    help.setPosition(8.f, world.y - barHeight + 3.f);
    target.draw(help);

    if (settings.paused)
    {
        sf::Text paused("PAUSED  -  P to resume, N for one step", font, 22);
        paused.setFillColor(sf::Color::White);
        paused.setOutlineColor(sf::Color::Black);
        paused.setOutlineThickness(2.f);
        const sf::FloatRect size = paused.getLocalBounds();
        paused.setPosition((world.x - size.width) / 2.f, 12.f);
        target.draw(paused);
    }
}

sf::View worldView(const Level& level, sf::Vector2u windowSize)
{
    const sf::Vector2f world = level.getWorldSize();
    sf::View view(sf::FloatRect(0.f, 0.f, world.x, world.y));
    view.setViewport(letterboxViewport(windowSize, world));
    return view;
}

void feedInput(Input& input, const sf::Event& event)
{
    switch (event.type)
    {
    case sf::Event::KeyPressed:
        input.setKeyDown(event.key.code);
        break;
    case sf::Event::KeyReleased:
        input.setKeyUp(event.key.code);
        break;
    case sf::Event::MouseButtonPressed:
    case sf::Event::MouseButtonReleased:
    {
        const bool down = event.type == sf::Event::MouseButtonPressed;
        if (event.mouseButton.button == sf::Mouse::Left)
            input.setMouseLDown(down);
        else if (event.mouseButton.button == sf::Mouse::Right)
            input.setMouseRDown(down);
        break;
    }
    case sf::Event::MouseWheelScrolled:
        input.addMouseWheel(event.mouseWheelScroll.delta);
        break;
    case sf::Event::LostFocus:
        input.releaseAll();
        break;
    default:
        break;
    }
}

} // namespace

int runWindow(Level& level, const Options& options, const ProgramInfo& info)
{
    const sf::Font font = loadFont();
    const sf::Vector2f world = level.getWorldSize();
    sf::RenderWindow window(
        sf::VideoMode(static_cast<unsigned>(world.x), static_cast<unsigned>(world.y)), info.title);
    window.setFramerateLimit(120);

    Input input;
    FixedStep fixedStep(stepSeconds);
    FrameSettings settings;
    settings.showDebug = options.debugBoxes;
    bool pausedByKey = false;
    bool pausedByFocus = false;
    sf::Vector2i mousePixel;
    sf::Clock frameClock;
    sf::Clock fpsClock;
    int framesCounted = 0;

    while (window.isOpen())
    {
        bool stepOnce = false;
        sf::Event event;
        while (window.pollEvent(event))
        {
            feedInput(input, event);
            if (event.type == sf::Event::Closed)
                window.close();
            else if (event.type == sf::Event::LostFocus)
                pausedByFocus = true;
            else if (event.type == sf::Event::GainedFocus)
                pausedByFocus = false;
            else if (event.type == sf::Event::MouseMoved)
                mousePixel = {event.mouseMove.x, event.mouseMove.y};
            else if (event.type == sf::Event::KeyPressed)
            {
                const sf::Keyboard::Key key = event.key.code;
                if (key == sf::Keyboard::F1)
                    settings.showDebug = !settings.showDebug;
                else if (key == sf::Keyboard::P)
                    pausedByKey = !pausedByKey;
                else if (key == sf::Keyboard::N)
                    stepOnce = true;
                else if (key == sf::Keyboard::F12)
                {
                    sf::Texture capture;
                    capture.create(window.getSize().x, window.getSize().y);
                    capture.update(window);
                    const std::string path = freeScreenshotName("", screenshotStamp());
                    const SaveResult saved = saveImage(capture.copyToImage(), path);
                    if (saved)
                        std::cout << "Saved " << path << std::endl;
                    else
                        std::cerr << "Could not save " << path << ": " << saved.problem
                                  << std::endl;
                }
                else if (key == sf::Keyboard::Escape && !level.handleEscape())
                    window.close();
            }
        }

        // Recomputed every frame, so the mouse is right after a resize or a view change.
        const sf::View view = worldView(level, window.getSize());
        input.setMousePosition(window.mapPixelToCoords(mousePixel, view));

        settings.paused = pausedByKey || pausedByFocus;
        const float frameSeconds = frameClock.restart().asSeconds();
        int steps = settings.paused ? 0 : fixedStep.advance(frameSeconds);
        if (settings.paused && stepOnce)
            steps = 1;
        for (int step = 0; step < steps; ++step)
        {
            level.handleInput(input, stepSeconds);
            level.update(stepSeconds);
            input.update(); // a press is seen by exactly one step
        }
        if (settings.paused)
            input.update(); // presses while paused are not saved up for later

        ++framesCounted;
        if (fpsClock.getElapsedTime().asSeconds() >= 0.5f)
        {
            settings.framesPerSecond =
                static_cast<int>(framesCounted / fpsClock.restart().asSeconds() + 0.5f);
            framesCounted = 0;
        }

        window.setView(view);
        drawFrame(window, level, font, settings);
        window.display();
    }
    return 0;
}

int saveScreenshot(Level& level, const Options& options, const ProgramInfo& info)
{
    const sf::Font font = loadFont();
    simulate(level, options.frames >= 0 ? options.frames : 0);

    const sf::Vector2f world = level.getWorldSize();
    sf::RenderTexture canvas;
    if (!canvas.create(static_cast<unsigned>(world.x), static_cast<unsigned>(world.y)))
    {
        std::cerr << info.title << ": could not create an image to draw into." << std::endl;
        return 1;
    }
    FrameSettings settings;
    settings.showDebug = options.debugBoxes;
    canvas.setView(sf::View(sf::FloatRect(0.f, 0.f, world.x, world.y)));
    drawFrame(canvas, level, font, settings);
    canvas.display();
    const SaveResult saved = saveImage(canvas.getTexture().copyToImage(), options.screenshotPath);
    if (!saved)
    {
        std::cerr << info.title << ": could not save '" << options.screenshotPath
                  << "': " << saved.problem << std::endl;
        return 1;
    }
    std::cout << info.title << ": saved " << options.screenshotPath << std::endl;
    return 0;
}

} // namespace hitbox
