#include "SandboxLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/objects/Collision.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

namespace
{
const sf::Vector2f cursorSize{90.f, 90.f};
const sf::Color obstacleColor{70, 90, 140};
const sf::Color overlappedColor{170, 70, 80};
} // namespace

SandboxLevel::SandboxLevel()
{
    addObstacle({200.f, 180.f}, {160.f, 100.f}, false);
    addObstacle({520.f, 150.f}, {120.f, 120.f}, true);
    addObstacle({860.f, 200.f}, {220.f, 60.f}, false);
    addObstacle({250.f, 460.f}, {90.f, 90.f}, true);
    addObstacle({600.f, 470.f}, {60.f, 180.f}, false);
    addObstacle({950.f, 460.f}, {160.f, 160.f}, true);
    // Two boxes side by side whose edges meet: the debug view's "touching" state.
    addObstacle({790.f, 580.f}, {100.f, 60.f}, false);
    addObstacle({890.f, 580.f}, {100.f, 60.f}, false);

    cursor.setSize(cursorSize);
    cursor.setOrigin(cursorSize / 2.f);
    cursor.setFillColor(sf::Color(240, 200, 80, 160));
}

void SandboxLevel::addObstacle(sf::Vector2f position, sf::Vector2f size, bool isCircle)
{
    Obstacle obstacle;
    obstacle.shape.setSize(size);
    obstacle.shape.setOrigin(size / 2.f);
    obstacle.shape.setPosition(position);
    obstacle.isCircle = isCircle;
    obstacles.push_back(obstacle);
}

// Boxes whose edges meet without sharing area (the edge rule's "touching").
bool SandboxLevel::edgesMeetAnother(const Obstacle& obstacle) const
{
    if (obstacle.isCircle)
        return false;
    const hitbox::Box a = hitbox::toBox(obstacle.shape.getCollisionBox());
    for (const Obstacle& other : obstacles)
    {
        if (&other == &obstacle || other.isCircle)
            continue;
        const hitbox::Box b = hitbox::toBox(other.shape.getCollisionBox());
        const bool reachX = a.left <= b.left + b.width && b.left <= a.left + a.width;
        const bool reachY = a.top <= b.top + b.height && b.top <= a.top + a.height;
        if (reachX && reachY && !hitbox::boxVsBox(a, b))
            return true;
    }
    return false;
}

// Overlapping the cursor shape; else touching another obstacle; else free.
hitbox::DebugState SandboxLevel::stateOf(const Obstacle& obstacle) const
{
    if (obstacle.overlapping)
        return hitbox::DebugState::Overlapping;
    return edgesMeetAnother(obstacle) ? hitbox::DebugState::Touching : hitbox::DebugState::Free;
}

void SandboxLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.getMousePosition() != lastMouseReading)
        mouse = input.getMousePosition();
    lastMouseReading = input.getMousePosition();
    if (input.isPressed(sf::Keyboard::Key::Space) || input.isLeftMousePressed())
        cursorIsCircle = !cursorIsCircle;
}

hitbox::Contact SandboxLevel::testCursorAgainst(Obstacle& obstacle)
{
    hitbox::GameObject* target = &obstacle.shape;
    if (cursorIsCircle && obstacle.isCircle)
        return hitbox::Collision::getBoundingCircleContact(&cursor, target);
    if (cursorIsCircle)
        return hitbox::Collision::getCircleBoxContact(&cursor, target);
    if (obstacle.isCircle)
    {
        // Box against circle: test it the other way round and flip the normal.
        hitbox::Contact contact = hitbox::Collision::getCircleBoxContact(target, &cursor);
        contact.normal = -contact.normal;
        return contact;
    }
    return hitbox::Collision::getBoundingBoxContact(&cursor, target);
}

void SandboxLevel::update(float)
{
    cursor.setPosition(mouse);
    for (Obstacle& obstacle : obstacles)
    {
        obstacle.contact = testCursorAgainst(obstacle);
        obstacle.overlapping = obstacle.contact.hit;
    }
}

void SandboxLevel::render(sf::RenderTarget& target) const
{
    for (const Obstacle& obstacle : obstacles)
    {
        const sf::Color fill = obstacle.overlapping ? overlappedColor : obstacleColor;
        if (obstacle.isCircle)
        {
            const hitbox::Circle circle = obstacle.shape.getBoundingCircle();
            sf::CircleShape drawn(circle.radius, 48);
            drawn.setOrigin({circle.radius, circle.radius});
            drawn.setPosition(hitbox::toSfml(circle.center));
            drawn.setFillColor(fill);
            target.draw(drawn);
        }
        else
        {
            sf::RectangleShape drawn = obstacle.shape;
            drawn.setFillColor(fill);
            target.draw(drawn);
        }
    }
    if (cursorIsCircle)
    {
        const hitbox::Circle circle = cursor.getBoundingCircle();
        sf::CircleShape drawn(circle.radius, 48);
        drawn.setOrigin({circle.radius, circle.radius});
        drawn.setPosition(hitbox::toSfml(circle.center));
        drawn.setFillColor(cursor.getFillColor());
        target.draw(drawn);
    }
    else
        target.draw(cursor);
}

// [slide:debug-render]
void SandboxLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    bool cursorOverlapping = false;
    for (const Obstacle& obstacle : obstacles)
    {
        if (obstacle.isCircle)
            debug.objectCircle(obstacle.shape, stateOf(obstacle));
        else
            debug.objectBox(obstacle.shape, stateOf(obstacle));
        // The normal says which way the cursor shape would be pushed out.
        debug.contact(obstacle.contact);
        cursorOverlapping = cursorOverlapping || obstacle.overlapping;
    }
    if (cursorIsCircle)
        debug.objectCircle(cursor, cursorOverlapping);
    else
        debug.objectBox(cursor, cursorOverlapping);
}
// [/slide]

std::string SandboxLevel::getHelpText() const
{
    return "Mouse move   Click/Space box or circle";
}

std::string SandboxLevel::describeState() const
{
    int overlapping = 0;
    for (const Obstacle& obstacle : obstacles)
        overlapping += obstacle.overlapping ? 1 : 0;
    return std::string("cursor ") + (cursorIsCircle ? "circle" : "box") + " overlapping " +
           std::to_string(overlapping) + " of " + std::to_string(obstacles.size()) + " shapes";
}
