#include "hitbox/app/private/Window.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Keys.h"
#include "hitbox/app/Letterbox.h"
#include "hitbox/app/Loop.h"
#include "hitbox/app/Screenshot.h"
#include "hitbox/app/private/LongRun.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/debug/TimelineStrip.h"
#include "hitbox/sfml/Events.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics.hpp>

#include <SFML/System/Err.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace hitbox
{
namespace
{

struct FrameSettings
{
    bool showDebug = false;
    bool paused = false;
    int framesPerSecond = 0;
    RewindTools rewind; // while paused: the strip and Left/Right
};

// Where the rewind strip lies: along the bottom, just above the help line.
Box stripArea(sf::Vector2f world)
{
    return {8.f, world.y - 24.f - 26.f, world.x - 16.f, 22.f};
}

bool canRewind(const FrameSettings& settings)
{
    return settings.paused && settings.rewind.rewind != nullptr &&
           settings.rewind.rewind->canRewind();
}

// The paused window's strip: the kept steps, the enters and exits among them, the step shown.
void drawRewindStrip(sf::RenderTarget& target, const Level& level, const FrameSettings& settings)
{
    const RewindLevel& rewind = *settings.rewind.rewind;
    std::vector<StripMark> marks;
    if (settings.rewind.timeline != nullptr)
        for (const TimelineEvent& event : settings.rewind.timeline->getEvents())
            if (event.kind != ContactPhase::Stay && event.step >= rewind.oldestStep())
                marks.push_back({event.step, event.kind == ContactPhase::Enter});
    drawTimelineStrip(target, stripArea(level.getWorldSize()),
                      {rewind.oldestStep(), rewind.newestStep(), rewind.shownStep()}, marks);
}

std::string helpLine(const Level& level, const FrameSettings& settings)
{
    // With F1 on, the line starts with what the debug cues mean, where it is never cut off.
    std::string line = settings.showDebug ? std::string(DebugRenderer::legend) + "   |   " : "";
    line += sharedKeysHelp();
    const std::string levelKeys = level.getHelpText();
    if (!levelKeys.empty())
        line += "   |   " + levelKeys;

    if (settings.framesPerSecond > 0)
        line += "   |   " + std::to_string(settings.framesPerSecond) + " fps";
    return line;
}

// The debug panel (DebugRenderer::panel): text lines on a dark box in the top-left corner.
void drawPanel(sf::RenderTarget& target, const sf::Font& font,
               const std::vector<std::string>& lines)
{
    if (lines.empty())
        return;
    const float lineHeight = 18.f;
    const float margin = 8.f;
    std::vector<sf::Text> texts;
    float width = 0.f;
    for (std::size_t i = 0; i < lines.size(); ++i)
    {
        texts.push_back(makeText(font, lines[i], 14));
        texts.back().setFillColor(sf::Color(235, 235, 235));
        texts.back().setPosition({2.f * margin, 2.f * margin + lineHeight * static_cast<float>(i)});
        width = std::max(width, rectSize(texts.back().getLocalBounds()).x);
    }
    sf::RectangleShape box(
        {width + 2.f * margin, lineHeight * static_cast<float>(lines.size()) + margin});
    box.setPosition({margin, margin});
    box.setFillColor(sf::Color(0, 0, 0, 200));
    target.draw(box);
    for (const sf::Text& text : texts)
        target.draw(text);
}

// Scene (`leftover` of a step after the last one, Loop.h), then debug shapes, then the help
// line: the same picture in the window and in a --screenshot file.
void drawFrame(sf::RenderTarget& target, const Level& level, const sf::Font& font,
               const FrameSettings& settings, float leftover)
{
    const sf::Vector2f world = level.getWorldSize();
    target.clear(DebugRenderer::backgroundColor);
    level.renderBlended(target, leftover);
    if (settings.showDebug)
    {
        DebugRenderer debug;
        level.renderDebug(debug);
        debug.draw(target);
        drawPanel(target, font, debug.getPanel());
    }

    const float barHeight = 24.f;
    sf::RectangleShape bar({world.x, barHeight});
    bar.setPosition({0.f, world.y - barHeight});
    bar.setFillColor(sf::Color(0, 0, 0, 170));
    target.draw(bar);
    sf::Text help = makeText(font, helpLine(level, settings), 14);
    help.setFillColor(sf::Color(220, 220, 220));
    help.setPosition({8.f, world.y - barHeight + 3.f});
    target.draw(help);

    if (canRewind(settings))
        drawRewindStrip(target, level, settings);
    if (settings.paused)
    {
        std::string title = "PAUSED  -  P to resume, N for one step";
        if (canRewind(settings))
            title = "PAUSED at step " + std::to_string(settings.rewind.rewind->shownStep()) +
                    "  -  Left/Right or click the strip: step back/forward, P resume";
        sf::Text paused = makeText(font, title, 22);
        paused.setFillColor(sf::Color::White);
        paused.setOutlineColor(sf::Color::Black);
        paused.setOutlineThickness(2.f);
        const float width = rectSize(paused.getLocalBounds()).x;
        paused.setPosition({(world.x - width) / 2.f, 12.f});
        target.draw(paused);
    }
}

// The window for a world: its size in pixels, shrunk (never stretched) to fit the desktop,
// so a 1000 x 1000 tile level asks for a window the screen can show, not 48000 x 48024 px.
sf::VideoMode windowMode(sf::Vector2f world)
{
    const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
    const sf::Vector2u screen = videoModeSize(desktop);
    const sf::Vector2u room = screen.x > 0 && screen.y > 0
                                  ? sf::Vector2u{screen.x / 10 * 9, screen.y / 10 * 9}
                                  // room for the title bar
                                  : sf::Vector2u{1920u, 1080u};
    const sf::Vector2u size = fitInside(world, room);
    return videoMode(size.x, size.y);
}

sf::View worldView(const Level& level, sf::Vector2u windowSize)
{
    const sf::Vector2f world = level.getWorldSize();
    sf::View view(sf::FloatRect({0.f, 0.f}, world));
    view.setViewport(letterboxViewport(windowSize, world));
    return view;
}

void feedInput(Input& input, const WindowEvent& event)
{
    using Kind = WindowEvent::Kind;
    const bool pressed = event.kind == Kind::MouseButtonPressed;
    switch (event.kind)
    {
    case Kind::KeyPressed:
        input.setKeyDown(static_cast<int>(event.key));
        break;
    case Kind::KeyReleased:
        input.setKeyUp(static_cast<int>(event.key));
        break;
    case Kind::MouseButtonPressed:
    case Kind::MouseButtonReleased:
        if (event.button == sf::Mouse::Button::Left)
            input.setMouseLDown(pressed);
        else if (event.button == sf::Mouse::Button::Right)
            input.setMouseRDown(pressed);
        break;
    case Kind::MouseWheelScrolled:
        input.addMouseWheel(event.wheelDelta);
        break;
    case Kind::FocusLost:
        input.releaseAll();
        break;
    default:
        break;
    }
}

// The loop's host with a window: events and the shared keys in, one drawn frame out.
class WindowHost : public LoopHost
{
public:
    WindowHost(Level& level, const Options& options, const ProgramInfo& info, RewindTools tools)
        : level(level), font(loadFont()), window(windowMode(level.getWorldSize()), info.title),
          stepsLeft(options.frames), pauseAtStep(options.pauseAtStep)
    {
        window.setFramerateLimit(static_cast<unsigned>(stepsPerSecond));
        settings.showDebug = options.debugBoxes;
        settings.rewind = tools;
    }

    // --frames N in a window: it closes after N steps (stepsLeft -1: runs until closed).
    bool isRunning() const override { return window.isOpen() && stepsLeft != 0; }

    // After a --frames run: the frames drawn per second over the whole run, the same count as
    // the help line's (which a long debug legend can push out of the window), so a script can
    // read how fast a scene draws. Nothing for a window the user closes.
    void reportFrameRate(const Options& options, const ProgramInfo& info) const
    {
        const float seconds = runClock.getElapsedTime().asSeconds();
        if (options.frames < 0 || seconds <= 0.f)
            return;
        std::cout << info.title << ": drew " << framesDrawn << " frames in " << seconds
                  << " s: " << static_cast<float>(framesDrawn) / seconds << " frames per second"
                  << std::endl;
    }

    float secondsSinceLastFrame() override { return frameClock.restart().asSeconds(); }

    void processInput(Input& input) override
    {
        if (settings.paused)
            input.update(); // presses while paused are not saved up for later
        stepOnce = false;
        WindowEvent event;
        while (pollEvent(window, event))
        {
            feedInput(input, event);
            if (event.kind == WindowEvent::Kind::Closed)
                window.close();
            else if (event.kind == WindowEvent::Kind::FocusLost)
                pausedByFocus = true;
            else if (event.kind == WindowEvent::Kind::FocusGained)
                pausedByFocus = false;
            else if (event.kind == WindowEvent::Kind::MouseMoved)
                mousePixel = event.mousePixel;
            else if (event.kind == WindowEvent::Kind::KeyPressed)
            {
                actOnSharedKey(findSharedKey(static_cast<int>(event.key)));
                rewindByKey(event.key);
            }
            else if (event.kind == WindowEvent::Kind::MouseButtonPressed &&
                     event.button == sf::Mouse::Button::Left)
                rewindByClick(mousePixel); // where the last move left the pointer
        }
        settings.paused = pausedByKey || pausedByFocus;
        // Recomputed every frame, so the mouse is right after a resize or a view change.
        input.setMousePosition(
            window.mapPixelToCoords(mousePixel, worldView(level, window.getSize())));
    }

    int stepsToRun(int due) override
    {
        int steps = due;
        if (settings.paused)
            steps = stepOnce ? 1 : 0;
        if (stepsLeft >= 0)
        {
            steps = static_cast<int>(std::min<long long>(steps, stepsLeft));
            stepsLeft -= steps;
        }
        if (pauseAtStep >= stepsRun && !settings.paused)
        {
            // --pause-at-step N: run up to step N exactly, then pause there.
            steps = static_cast<int>(std::min<long long>(steps, pauseAtStep - stepsRun));
            if (stepsRun + steps == pauseAtStep)
                pausedByKey = settings.paused = true;
        }
        stepsRun += steps;
        return steps;
    }

    void render(const Level& drawn, float leftover) override
    {
        countFrame();
        window.setView(worldView(drawn, window.getSize()));
        // Paused, the picture is the step itself (what N and --pause-at-step stop at).
        drawFrame(window, drawn, font, settings, settings.paused ? 1.f : leftover);
        window.display();
    }

private:
    // Paused: Left and Right step back and forward through the kept steps (Rewind.h).
    void rewindByKey(sf::Keyboard::Key key)
    {
        if (!canRewind(settings))
            return;
        RewindLevel& rewind = *settings.rewind.rewind;
        if (key == sf::Keyboard::Key::Left)
            rewind.show(rewind.shownStep() - 1);
        else if (key == sf::Keyboard::Key::Right)
            rewind.show(rewind.shownStep() + 1);
    }

    // Paused: a click on the strip shows the step under it.
    void rewindByClick(sf::Vector2i pixel)
    {
        if (!canRewind(settings))
            return;
        const sf::Vector2f at = window.mapPixelToCoords(pixel, worldView(level, window.getSize()));
        const Box area = stripArea(level.getWorldSize());
        if (at.y < area.top || at.y > area.top + area.height)
            return;
        RewindLevel& rewind = *settings.rewind.rewind;
        rewind.show(stripStepAt(
            area, {rewind.oldestStep(), rewind.newestStep(), rewind.shownStep()}, at.x));
    }

    void actOnSharedKey(const SharedKey* shared)
    {
        if (shared == nullptr)
            return;
        switch (shared->action)
        {
        case SharedAction::ToggleDebug:
            settings.showDebug = !settings.showDebug;
            break;
        case SharedAction::Pause:
            pausedByKey = !pausedByKey;
            break;
        case SharedAction::Step:
            stepOnce = true;
            break;
        case SharedAction::Screenshot:
            saveWindowPicture();
            break;
        case SharedAction::Quit:
            if (!level.handleEscape())
                window.close();
            break;
        }
    }

    void saveWindowPicture()
    {
        const std::string path = freeScreenshotName("", screenshotStamp());
        const SaveResult saved = saveImage(captureWindow(window), path);
        if (saved)
            std::cout << "Saved " << path << std::endl;
        else
            std::cerr << "Could not save " << path << ": " << saved.problem << std::endl;
    }

    // Frames per second for the help line, measured over half a second.
    void countFrame()
    {
        ++framesCounted;
        ++framesDrawn;
        if (fpsClock.getElapsedTime().asSeconds() >= 0.5f)
        {
            settings.framesPerSecond =
                static_cast<int>(framesCounted / fpsClock.restart().asSeconds() + 0.5f);
            framesCounted = 0;
        }
    }

    Level& level;
    const sf::Font font;
    sf::RenderWindow window;
    FrameSettings settings;
    bool pausedByKey = false;
    bool pausedByFocus = false;
    bool stepOnce = false;
    sf::Vector2i mousePixel;
    sf::Clock frameClock;
    sf::Clock fpsClock;
    sf::Clock runClock;
    int framesCounted = 0;
    long long framesDrawn = 0;
    long long stepsLeft;
    long long pauseAtStep;
    long long stepsRun = 0;
};

} // namespace

int runWindow(Level& level, const Options& options, const ProgramInfo& info, RewindTools tools)
{
    WindowHost host(level, options, info, tools);
    runLoop(level, host);
    host.reportFrameRate(options, info);
    return 0;
}

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

} // namespace hitbox
