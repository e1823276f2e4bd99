// ManyObjectsDrawing.cpp - everything ManyObjectsLevel draws: the balls (one vertex array),
// the pair table, the readout and the debug view. Reads the simulation, changes nothing.
#include "ManyObjectsLevel.h"

#include "hitbox/app/Assets.h"
#include "hitbox/broadphase/Broadphase.h"
#include "hitbox/debug/BroadphaseDrawing.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/sfml/Conversions.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/PrimitiveType.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderStates.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <vector>

namespace
{
// The balls' colours, all opaque, so the batch draws without blending (renderStatesFor); a
// see-through one would turn blending on and still draw right.
const sf::Color plainColor{90, 160, 230};
const sf::Color shipColors[] = {{80, 210, 255}, {255, 160, 60}};
const sf::Color bulletColors[] = {{170, 235, 255}, {255, 215, 150}};
const sf::Color pickupColor{235, 215, 70};

const sf::Color cellUntested{44, 48, 60};
const sf::Color cellTested{95, 110, 135};
const sf::Color cellWasted{210, 60, 210}; // on or below the diagonal, or tested twice

const hitbox::Box tableArea{660.f, 60.f, 500.f, 500.f};

// Balls smaller than this are drawn as squares: two triangles instead of a dozen, and at
// that size nobody can tell.
const float squareBelowRadius = 2.5f;
// Triangles around a disc: edges about this many pixels long, so a ball gets as few corners as
// its size allows (a 5 px ball 7, a 15 px one 23) and no big ball looks like a polygon.
const float discEdgePixels = 4.f;
const int fewestDiscSegments = 6;
const int mostDiscSegments = 32;

// Above this many balls the debug view draws the grid's lines but not its busy cells: at
// 10,000 balls that is thousands of outlines, most of the grid, and the software renderer
// drew 4 frames a second instead of 17 (docs/performance.md).
const std::size_t busyCellsUpToBalls = 3000;

sf::Color colorOf(const Ball& ball)
{
    if (ball.responses > 0 && ball.kind != BallKind::Bullet)
        return hitbox::DebugRenderer::overlappingColor;
    switch (ball.kind)
    {
    case BallKind::Ship:
        return shipColors[ball.owner == 0 ? 0 : 1];
    case BallKind::Bullet:
        return bulletColors[ball.owner == 0 ? 0 : 1];
    case BallKind::Pickup:
        return pickupColor;
    default:
        return plainColor;
    }
}

void addTriangle(sf::VertexArray& vertices, sf::Vector2f a, sf::Vector2f b, sf::Vector2f c,
                 sf::Color color)
{
    vertices.append({a, color});
    vertices.append({b, color});
    vertices.append({c, color});
}

void addQuad(sf::VertexArray& vertices, const hitbox::Box& box, sf::Color color)
{
    const sf::Vector2f topLeft{box.left, box.top};
    const sf::Vector2f topRight{box.left + box.width, box.top};
    const sf::Vector2f bottomLeft{box.left, box.top + box.height};
    const sf::Vector2f bottomRight{box.left + box.width, box.top + box.height};
    addTriangle(vertices, topLeft, topRight, bottomRight, color);
    addTriangle(vertices, topLeft, bottomRight, bottomLeft, color);
}

int discSegments(float radius)
{
    const float perimeter = 2.f * hitbox::pi * radius;
    return std::clamp(static_cast<int>(perimeter / discEdgePixels), fewestDiscSegments,
                      mostDiscSegments);
}

void addDisc(std::vector<sf::Vertex>& vertices, sf::Vector2f center, float radius, sf::Color color)
{
    const int segments = discSegments(radius);
    const float step = 2.f * hitbox::pi / static_cast<float>(segments);
    sf::Vector2f previous = center + sf::Vector2f(radius, 0.f);
    for (int i = 1; i <= segments; ++i)
    {
        const float angle = step * static_cast<float>(i);
        const sf::Vector2f next = center + sf::Vector2f(std::cos(angle), std::sin(angle)) * radius;
        vertices.push_back({center, color});
        vertices.push_back({previous, color});
        vertices.push_back({next, color});
        previous = next;
    }
}

// A small ball as a square: two triangles.
void addSquare(std::vector<sf::Vertex>& vertices, const hitbox::Box& box, sf::Color color)
{
    const sf::Vector2f topLeft{box.left, box.top};
    const sf::Vector2f topRight{box.left + box.width, box.top};
    const sf::Vector2f bottomLeft{box.left, box.top + box.height};
    const sf::Vector2f bottomRight{box.left + box.width, box.top + box.height};
    for (const sf::Vector2f& corner :
         {topLeft, topRight, bottomRight, topLeft, bottomRight, bottomLeft})
        vertices.push_back({corner, color});
}

// 12345678 -> "12,345,678": big counts are the point of this lab, so make them readable.
std::string withCommas(std::size_t number)
{
    std::string digits = std::to_string(number);
    for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3)
        digits.insert(static_cast<std::size_t>(at), ",");
    return digits;
}

std::string fixed(float value, int decimals)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.*f", decimals, static_cast<double>(value));
    return text;
}

sf::Text makeText(const std::string& text, const sf::Font& font, unsigned size, sf::Color color)
{
    sf::Text label = hitbox::makeText(font, sf::String::fromUtf8(text.begin(), text.end()), size);
    label.setFillColor(color);
    return label;
}

} // namespace

void ManyObjectsLevel::render(sf::RenderTarget& target) const
{
    drawBalls(target);
    if (scene == Scene::PairTable)
        drawPairTable(target);
    drawReadout(target);
}

// [slide:lab08-batched-draw]
void ManyObjectsLevel::drawBalls(sf::RenderTarget& target) const
{
    // Every ball goes into ONE vertex array, drawn in a few big calls (hitbox::drawTriangles
    // says why). 10,000 sf::CircleShape draws would cost more than all the collision
    // detection. The array is last frame's, refilled.
    ballVertices.clear();
    bool allOpaque = true; // opaque colours can skip blending (renderStatesFor)
    for (const Ball& ball : balls)
    {
        const sf::Color color = colorOf(ball);
        allOpaque = allOpaque && color.a == 255;
        if (ball.radius < squareBelowRadius)
            addSquare(ballVertices, ball.box(), color);
        else
            addDisc(ballVertices, hitbox::toSfml(ball.position), ball.radius, color);
    }
    hitbox::drawTriangles(target, ballVertices.data(), ballVertices.size(),
                          hitbox::renderStatesFor(allOpaque));
}
// [/slide]

void ManyObjectsLevel::drawPairTable(sf::RenderTarget& target) const
{
    const sf::Font& labelFont = font.get();
    // Numbers on the balls, so a cell (i, j) can be found in the picture.
    for (std::size_t i = 0; i < balls.size(); ++i)
    {
        sf::Text number = makeText(std::to_string(i), labelFont, 20, sf::Color::Black);
        const hitbox::Box bounds = hitbox::toBox(number.getLocalBounds());
        number.setPosition({balls[i].position.x - bounds.width / 2.f - bounds.left,
                            balls[i].position.y - bounds.height / 2.f - bounds.top});
        target.draw(number);
    }

    const std::size_t count = table.size();
    if (count == 0)
        return;
    const float cell =
        std::min(40.f, std::min(tableArea.width, tableArea.height) / static_cast<float>(count + 1));
    const sf::Vector2f origin{tableArea.left + cell, tableArea.top + cell};
    sf::VertexArray cells(sf::PrimitiveType::Triangles);
    for (std::uint32_t row = 0; row < count; ++row)
        for (std::uint32_t column = 0; column < count; ++column)
        {
            const int tests = table.timesTested(row, column);
            const bool aboveDiagonal = column > row;
            if (!aboveDiagonal && tests == 0)
                continue;
            sf::Color color = cellUntested;
            if (!aboveDiagonal || tests > 1)
                color = cellWasted;
            else if (table.isOverlapping(row, column))
                color = hitbox::DebugRenderer::overlappingColor; // read here: set in another file
            else if (tests == 1)
                color = cellTested;
            const hitbox::Box box{origin.x + column * cell + 1.f, origin.y + row * cell + 1.f,
                                  cell - 2.f, cell - 2.f};
            addQuad(cells, box, color);
        }
    target.draw(cells);

    const unsigned labelSize = static_cast<unsigned>(std::max(9.f, cell * 0.45f));
    for (std::uint32_t i = 0; i < count; ++i)
    {
        sf::Text columnLabel = makeText(std::to_string(i), labelFont, labelSize, sf::Color::White);
        columnLabel.setPosition({origin.x + i * cell + cell * 0.25f, origin.y - cell * 0.85f});
        target.draw(columnLabel);
        sf::Text rowLabel = columnLabel;
        rowLabel.setPosition({tableArea.left + cell * 0.2f, origin.y + i * cell + cell * 0.15f});
        target.draw(rowLabel);
    }

    const std::size_t allPairs = count * (count - 1) / 2;
    sf::Text title = makeText("The pair table: " + std::to_string(count) + " balls, " +
                                  std::to_string(count) + "\xc2\xb7" + std::to_string(count - 1) +
                                  "/2 = " + std::to_string(allPairs) + " pairs",
                              labelFont, 18, sf::Color::White);
    title.setPosition({tableArea.left, tableArea.top - 40.f});
    target.draw(title);
    sf::Text key = makeText("grey tested   vermillion overlapping   dark skipped by the rules   "
                            "purple wasted",
                            labelFont, 13, sf::Color(200, 200, 200));
    key.setPosition({tableArea.left, tableArea.top - 16.f});
    target.draw(key);
}

void ManyObjectsLevel::drawReadout(sf::RenderTarget& target) const
{
    const char* sceneNames[] = {"1 crowd", "2 pair table", "3 layers"};
    std::string lines = std::string("Scene ") + sceneNames[static_cast<int>(scene)] +
                        "    balls: " + withCommas(balls.size()) +
                        "    method: " + methodLabel(method) + "  (M)";
    if (method == hitbox::BroadphaseMethod::Grid)
    {
        // The cell the grid used in the last step, in pixels and in the balls' average width.
        const hitbox::BroadphaseLayout grid = broadphase->layout();
        const float widths = grid.averageSide > 0.f ? grid.cellSize / grid.averageSide : 0.f;
        lines += "    grid cell: " + fixed(grid.cellSize, 0) + " px = " + fixed(widths, 2) +
                 " ball widths  ([ ])";
    }
    lines += "\n";
    sf::Color color = sf::Color::White;
    if (bruteForceSkipped)
    {
        const std::size_t n = balls.size();
        lines += "brute force would test " + withCommas(n * (n - 1) / 2) +
                 " pairs every step: not run above " + withCommas(bruteForceBallLimit) +
                 " balls. Press M.\n";
        color = sf::Color(255, 190, 90);
    }
    else if (stoppedAsTooSlow)
    {
        lines += std::string(methodLabel(method)) + " took " + fixed(collisionMilliseconds, 0) +
                 " ms per step with " + withCommas(balls.size()) +
                 " balls: stopped, too slow to watch. Press M or Down.\n";
        color = sf::Color(255, 190, 90);
    }
    // The timings go last. A --screenshot picture leaves them out (showTimings): it must be
    // the same on every run, and the slides' figures are drawn twice and compared.
    std::string timing;
    if (!bruteForceSkipped && !stoppedAsTooSlow)
    {
        lines += "pairs tested: " + withCommas(getPairsTested()) +
                 "    boxes overlapping: " + withCommas(candidatePairs.size()) +
                 "    circles touching: " + withCommas(contacts) + "\n";
        if (showTimings)
        {
            timing = "collision: " + fixed(collisionMilliseconds, 2) + " ms CPU per step";
            if (stepsMeasured > 1)
                timing += "    real time: " + fixed(realStepMilliseconds, 1) + " ms per step";
        }
        else
            timing = "collision timing: not in a --screenshot picture (F12 in the window)";
        timing += "\n";
    }
    if (scene == Scene::PairTable)
        lines += "your loop tested " + withCommas(table.testsMade()) + " pairs, found " +
                 withCommas(table.overlappingPairs().size()) + " overlapping\n";
    if (scene == Scene::Layers)
    {
        lines += "bullets hitting their own ship: " + withCommas(ownShipHits) +
                 "    pickups bumping pickups: " + withCommas(pickupBumps) + "\n";
        if (ownShipHits + pickupBumps > 0)
            color = sf::Color(255, 150, 130);
    }
    lines += timing;

    sf::Text text = makeText(lines, font.get(), 16, color);
    // Between the arena and the help bar, the full width of the world.
    const sf::Vector2f world = getWorldSize();
    const float top = getArena().top + getArena().height;
    sf::RectangleShape panel({world.x, world.y - top});
    panel.setPosition({0.f, top});
    panel.setFillColor(sf::Color(30, 34, 46));
    target.draw(panel);
    text.setPosition({10.f, top + 4.f});
    target.draw(text);
}

std::string ManyObjectsLevel::timingLine() const
{
    return "timing: " + std::string(methodLabel(method)) + ", " + std::to_string(balls.size()) +
           " balls, " + std::to_string(threads) + (threads == 1 ? " thread: " : " threads: ") +
           std::to_string(getPairsTested()) + " pairs tested, " +
           std::to_string(candidatePairs.size()) + " overlapping; " +
           describeTiming(getTimingSummary(), stepBudgetMilliseconds) + "; real time " +
           fixed(realStepMilliseconds, 1) + " ms/step (wall clock)" +
           (bruteForceSkipped ? " (brute force skipped)" : "") +
           (stoppedAsTooSlow ? " (stopped: too slow)" : "");
}

void ManyObjectsLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    if (scene != Scene::PairTable && !bruteForceSkipped && !stoppedAsTooSlow)
    {
        hitbox::BroadphaseLayout layout = broadphase->layout();
        if (balls.size() > busyCellsUpToBalls)
            std::fill(layout.boxesPerCell.begin(), layout.boxesPerCell.end(), 0u);
        hitbox::drawBroadphase(debug, layout);
    }
    // The boxes the pair loop compares, for the scenes small enough to read them.
    if (balls.size() <= 300)
        for (const Ball& ball : balls)
            debug.box(ball.box(), ball.responses > 0 ? hitbox::DebugRenderer::overlappingColor
                                                     : hitbox::DebugRenderer::freeColor);
}
