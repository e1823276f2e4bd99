#include "hitbox/app/private/Window.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Keys.h"
#include "hitbox/app/Letterbox.h"
#include "hitbox/app/Loop.h"
#include "hitbox/app/private/FeedInput.h"
#include "hitbox/app/private/Frame.h"
#include "hitbox/app/private/FrameRate.h"
#include "hitbox/app/private/ScreenshotRun.h"
#include "hitbox/sfml/Events.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/View.hpp>
#include <SFML/System/Clock.hpp>
#include <SFML/System/Time.hpp>
#include <SFML/Window/VideoMode.hpp>

#include <algorithm>
#include <string>

namespace hitbox
{
namespace
{

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
    void reportFrameRate(const Options& options, const ProgramInfo& info) const
    {
        frameRate.report(options, info);
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
        if (wantedStep >= 0 && canRewind(settings.rewind, settings.paused))
            settings.rewind.rewind->show(wantedStep);
        wantedStep = -1;
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
            {
                pausedByKey = settings.paused = true;
                pauseAtStep = -1; // once: P then resumes (it had paused again at once)
            }
        }
        stepsRun += steps;
        return steps;
    }

    void render(const Level& drawn, float leftover) override
    {
        settings.framesPerSecond = frameRate.countFrame();
        window.setView(worldView(drawn, window.getSize()));
        // Paused, the picture is the step itself (what N and --pause-at-step stop at).
        drawFrame(window, drawn, font, settings, settings.paused ? 1.f : leftover);
        window.display();
    }

private:
    // Paused: Left/Right and a click on the strip choose the step shown (RewindStrip.h); it
    // is shown once, after the frame's events.
    void rewindByKey(sf::Keyboard::Key key)
    {
        if (!canRewind(settings.rewind, settings.paused))
            return;
        const RewindLevel& rewind = *settings.rewind.rewind;
        const long long from = wantedStep >= 0 ? wantedStep : rewind.shownStep();
        wantedStep = std::clamp(stepForKey(from, key), rewind.oldestStep(), rewind.newestStep());
    }

    void rewindByClick(sf::Vector2i pixel)
    {
        if (!canRewind(settings.rewind, settings.paused))
            return;
        const long long at =
            stepForClick(*settings.rewind.rewind, level.getWorldSize(),
                         window.mapPixelToCoords(pixel, worldView(level, window.getSize())));
        if (at >= 0)
            wantedStep = at;
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
            saveWindowPicture(window);
            break;
        case SharedAction::Quit:
            if (!level.handleEscape())
                window.close();
            break;
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
    long long wantedStep = -1; // the step this frame's rewind keys and clicks ask for
    sf::Clock frameClock;
    FrameRate frameRate;
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

} // namespace hitbox
