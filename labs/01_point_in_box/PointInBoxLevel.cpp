#include "PointInBoxLevel.h"

#include "PointInPolygon.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Vec2.h"
#include "hitbox/objects/Collision.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
struct BoxSetup
{
    sf::Vector2f position; // top-left corner, in scene coordinates
    sf::Vector2f size;
    sf::Color color;
};

// Two pairs overlap on purpose: where they do, the box drawn last (on top) is the one
// the mouse points at.
const BoxSetup boxSetups[] = {
    {{120.f, 110.f}, {220.f, 140.f}, {70, 110, 190}},
    {{400.f, 170.f}, {140.f, 140.f}, {190, 90, 70}},
    {{760.f, 90.f}, {300.f, 90.f}, {80, 160, 100}},
    {{180.f, 400.f}, {260.f, 160.f}, {150, 90, 170}},
    {{360.f, 470.f}, {160.f, 120.f}, {200, 150, 60}},
    {{700.f, 360.f}, {120.f, 220.f}, {60, 150, 160}},
    {{870.f, 400.f}, {200.f, 200.f}, {170, 70, 110}},
    {{800.f, 330.f}, {120.f, 90.f}, {110, 120, 130}},
};

// The star of task 4: a concave polygon, where a box test would light up its gaps too.
const sf::Vector2f starCenter{650.f, 255.f};
const float starOuterRadius = 85.f;
const float starInnerRadius = 36.f;
const int starPoints = 5;
const sf::Color starColor{90, 140, 200};

const sf::Color hoverOutline{255, 255, 255};
const sf::Color selectedOutline{255, 220, 60};
} // namespace

PointInBoxLevel::PointInBoxLevel()
{
    for (const BoxSetup& setup : boxSetups)
    {
        hitbox::GameObject box;
        box.setSize(setup.size);
        box.setPosition(setup.position);
        box.setFillColor(setup.color);
        boxes.push_back(box);
    }
    // Corners alternate between the outer and inner radius, the first pointing straight up.
    for (int corner = 0; corner < 2 * starPoints; ++corner)
    {
        const float radius = corner % 2 == 0 ? starOuterRadius : starInnerRadius;
        const float angle = hitbox::pi * (static_cast<float>(corner) / starPoints - 0.5f);
        star.push_back(starCenter +
                       sf::Vector2f(radius * std::cos(angle), radius * std::sin(angle)));
    }
    // No update() here: it runs every task's code, and a test of one task builds a level too
    // (one mistake must cost one task). The first step, 1/120 s in, shows the hovered box.
}

void PointInBoxLevel::handleInput(const hitbox::Input& input, float)
{
    // Follow the mouse once it moves (until then, keep the starting point: see the header).
    if (input.getMousePosition() != lastMouseReading)
        mouseInWindow = input.getMousePosition();
    lastMouseReading = input.getMousePosition();
    mouseDown = input.isLeftMouseDown();
    mousePressed = input.isLeftMousePressed();

    int zoomNotches = 0;
    if (input.getMouseWheel() > 0.f || input.isPressed(sf::Keyboard::Key::Equal) ||
        input.isPressed(sf::Keyboard::Key::Add))
        zoomNotches = 1;
    if (input.getMouseWheel() < 0.f || input.isPressed(sf::Keyboard::Key::Hyphen) ||
        input.isPressed(sf::Keyboard::Key::Subtract))
        zoomNotches = -1;
    if (zoomNotches > 0)
        zoom = std::min(zoom * zoomStep, maxZoom);
    if (zoomNotches < 0)
        zoom = std::max(zoom / zoomStep, minZoom);
    if (input.isPressed(sf::Keyboard::Key::Num0) || input.isPressed(sf::Keyboard::Key::Numpad0))
        zoom = 1.f;
}

// [slide:lab01-point-in-box]
// Which box is the mouse over? Collision::checkBoundingBox(object, point) asks whether a
// point lies strictly inside the object's collision box: on an edge is outside (touching
// is not colliding, the edge rule of hitbox/geometry/Overlap.h).
int PointInBoxLevel::findBoxUnder(sf::Vector2f scenePoint)
{
    // BEGIN TASK 1: find the box under the mouse
    // Boxes drawn later cover earlier ones, so the top box is the last one that matches.
    for (int index = getBoxCount() - 1; index >= 0; --index)
    {
        if (hitbox::Collision::checkBoundingBox(&boxes[index], scenePoint))
            return index;
    }
    return noBox;
    // STARTER TASK 1
    // (void)scenePoint;
    // return noBox;
    // END TASK 1
}
// [/slide]

// [slide:lab01-mouse-world]
// The camera draws scene point p at getCamera().transformPoint(p) in the window. The mouse
// arrives in window coordinates (Hitbox already undid the window's own resize and letterbox
// with mapPixelToCoords), so to compare it with the boxes we undo the camera as well.
sf::Vector2f PointInBoxLevel::windowToScene(sf::Vector2f windowPoint) const
{
    // BEGIN TASK 3: the mouse in scene coordinates, zoomed
    return getCamera().getInverse().transformPoint(windowPoint);
    // STARTER TASK 3
    // return windowPoint;
    // END TASK 3
}
// [/slide]

void PointInBoxLevel::update(float)
{
    mouseInScene = windowToScene(mouseInWindow);
    hoveredBox = findBoxUnder(mouseInScene);
    dragBox(hoveredBox, mouseInScene);
    starHovered = isInsidePolygon(star, mouseInScene);
}

void PointInBoxLevel::dragBox(int boxUnderMouse, sf::Vector2f mouse)
{
    // BEGIN TASK 2: pick up, drag and drop a box
    // Keep the offset from the mouse to the box, so the box does not jump to put its
    // corner under the mouse when you grab it by the middle.
    if (mousePressed && boxUnderMouse != noBox)
    {
        selectedBox = boxUnderMouse;
        grabOffset = boxes[selectedBox].getPosition() - mouse;
    }
    if (!mouseDown)
        selectedBox = noBox;
    if (selectedBox != noBox)
        boxes[selectedBox].setPosition(mouse + grabOffset);
    // STARTER TASK 2
    // (void)boxUnderMouse;
    // (void)mouse;
    // END TASK 2
}

void PointInBoxLevel::render(sf::RenderTarget& target) const
{
    const sf::RenderStates camera(getCamera());
    for (int index = 0; index < getBoxCount(); ++index)
    {
        sf::RectangleShape drawn = boxes[index];
        if (index == selectedBox)
        {
            drawn.setOutlineThickness(-6.f);
            drawn.setOutlineColor(selectedOutline);
        }
        else if (index == hoveredBox)
        {
            drawn.setOutlineThickness(-4.f);
            drawn.setOutlineColor(hoverOutline);
            const sf::Color fill = drawn.getFillColor();
            drawn.setFillColor(sf::Color(std::min(255, fill.r + 50), std::min(255, fill.g + 50),
                                         std::min(255, fill.b + 50)));
        }
        target.draw(drawn, camera);
    }

    // The star, as a fan of triangles from its middle (it is concave, so sf::ConvexShape
    // would draw it wrong); brighter while the mouse is inside it.
    sf::VertexArray starFan(sf::PrimitiveType::TriangleFan);
    const sf::Color fill =
        starHovered ? sf::Color(std::min(255, starColor.r + 70), std::min(255, starColor.g + 70),
                                std::min(255, starColor.b + 55))
                    : starColor;
    starFan.append(sf::Vertex{starCenter, fill});
    for (const sf::Vector2f& corner : star)
        starFan.append(sf::Vertex{corner, fill});
    starFan.append(sf::Vertex{star.front(), fill});
    target.draw(starFan, camera);

    // A crosshair where the level thinks the mouse is (screenshots have no mouse pointer).
    sf::CircleShape ring(7.f);
    ring.setOrigin({7.f, 7.f});
    ring.setPosition(mouseInWindow);
    ring.setFillColor(sf::Color::Transparent);
    ring.setOutlineThickness(2.f);
    ring.setOutlineColor(sf::Color::White);
    target.draw(ring);
}

void PointInBoxLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    // The debug renderer draws in window coordinates, so each box goes through the camera.
    const sf::Transform camera = getCamera();
    for (int index = 0; index < getBoxCount(); ++index)
    {
        const sf::FloatRect onScreen = camera.transformRect(boxes[index].getCollisionBox());
        debug.box(hitbox::toBox(onScreen),
                  index == hoveredBox ? hitbox::DebugState::Overlapping : hitbox::DebugState::Free);
    }
    debug.cross(hitbox::toVec2(getCamera().transformPoint(mouseInScene)), 10.f,
                hitbox::DebugRenderer::hintColor);
}

std::string PointInBoxLevel::getHelpText() const
{
    return "Mouse point   Hold left button drag   Wheel or +/- zoom   0 reset zoom";
}

std::string PointInBoxLevel::describeState() const
{
    char text[120];
    std::snprintf(text, sizeof text, "hovered box %d, selected box %d, zoom %.2f", hoveredBox,
                  selectedBox, static_cast<double>(zoom));
    return text;
}

int PointInBoxLevel::getBoxCount() const
{
    return static_cast<int>(boxes.size());
}

const hitbox::GameObject& PointInBoxLevel::getBox(int index) const
{
    return boxes.at(static_cast<std::size_t>(index));
}

int PointInBoxLevel::getHoveredBox() const
{
    return hoveredBox;
}

int PointInBoxLevel::getSelectedBox() const
{
    return selectedBox;
}

float PointInBoxLevel::getZoom() const
{
    return zoom;
}

sf::Transform PointInBoxLevel::getCamera() const
{
    // Scale about the middle of the window: move the middle to (0, 0), scale, move back.
    const sf::Vector2f middle = getWorldSize() / 2.f;
    sf::Transform camera;
    camera.translate(middle).scale({zoom, zoom}).translate(-middle);
    return camera;
}

sf::Vector2f PointInBoxLevel::getMouseInScene() const
{
    return mouseInScene;
}

const std::vector<sf::Vector2f>& PointInBoxLevel::getStar() const
{
    return star;
}

bool PointInBoxLevel::isStarHovered() const
{
    return starHovered;
}
