#include "DepotLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/debug/ExplainOverlay.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/objects/ExplainPair.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace
{
sf::Vector2f sizeOf(const hitbox::Box& box)
{
    return {box.width, box.height};
}

sf::Vector2f topLeftOf(const hitbox::Box& box)
{
    return {box.left, box.top};
}

// The edges of `a` and `b` meet and they share no area (drawn dashed in the debug view).
bool touching(const hitbox::Box& a, const hitbox::Box& b)
{
    const bool reachX = a.left <= b.left + b.width && b.left <= a.left + a.width;
    const bool reachY = a.top <= b.top + b.height && b.top <= a.top + a.height;
    return reachX && reachY && !hitbox::boxVsBox(a, b);
}

void drawBox(sf::RenderTarget& target, const hitbox::Box& box, sf::Color fill,
             sf::Color outline = sf::Color::Transparent)
{
    sf::RectangleShape shape(sizeOf(box));
    shape.setPosition(topLeftOf(box));
    shape.setFillColor(fill);
    shape.setOutlineColor(outline);
    shape.setOutlineThickness(outline == sf::Color::Transparent ? 0.f : -3.f);
    target.draw(shape);
}
} // namespace

DepotLevel::DepotLevel()
{
    start();
}

void DepotLevel::start()
{
    // The World points at the objects: empty it before they are destroyed.
    world.clear();
    crates.clear();
    plate = std::make_unique<PressurePlate>(topLeftOf(plateBox), sizeOf(plateBox));
    plate->setName("plate");
    gateway = std::make_unique<Piece>(Kind::Gateway, topLeftOf(gatewayBox), sizeOf(gatewayBox));
    gateway->setName("gateway");
    dropZone = std::make_unique<Piece>(Kind::DropZone, topLeftOf(dropZoneBox), sizeOf(dropZoneBox));
    dropZone->setName("drop zone");
    guard = std::make_unique<Piece>(Kind::Guard, guardStart, sf::Vector2f{guardSize, guardSize});
    guard->setName("gatekeeper");
    guard->setFillColor({230, 159, 0});
    // [slide:depot-triggers]
    using Body = hitbox::World::Body;
    const hitbox::World::Shape box = hitbox::World::Shape::Box;
    world.add(*plate, layer::zone, layer::crate, box, Body::Trigger);
    world.add(*gateway, layer::zone, layer::crate | layer::guard, box, Body::Trigger);
    world.add(*dropZone, layer::zone, layer::crate, box, Body::Trigger);
    world.add(*guard, layer::guard, layer::zone, box, Body::Trigger);
    // [/slide]
    guardDirection = {};
    steps = 0;
    cratesMade = 0;
    delivered = 0;
    gateOpen = false;
}

void DepotLevel::handleInput(const hitbox::Input& input, float)
{
    mouse = input.getMousePosition();
    if (input.isPressed(sf::Keyboard::Key::R))
        start();
    guardDirection.x = (input.isKeyDown(sf::Keyboard::Key::Right) ? 1.f : 0.f) -
                       (input.isKeyDown(sf::Keyboard::Key::Left) ? 1.f : 0.f);
    guardDirection.y = (input.isKeyDown(sf::Keyboard::Key::Down) ? 1.f : 0.f) -
                       (input.isKeyDown(sf::Keyboard::Key::Up) ? 1.f : 0.f);
}

// Each belt brings a crate at its own beat; the lower belt's crate waits when the belt's start
// is still taken by the queue.
void DepotLevel::spawnCrates()
{
    const auto make = [this](float top)
    {
        crates.push_back(std::make_unique<Crate>(sf::Vector2f{0.f, top}));
        crates.back()->setName("crate " + std::to_string(++cratesMade));
        world.add(*crates.back(), layer::crate, layer::zone);
    };
    if (steps % upperBeltSteps == 0)
        make(upperBeltTop);
    if (steps % lowerBeltSteps == 0)
    {
        bool room = true;
        for (const std::unique_ptr<Crate>& crate : crates)
            if (crate->getPosition().y == lowerBeltTop && crate->getPosition().x < crateSize)
                room = false;
        if (room)
            make(lowerBeltTop);
    }
}

// Every crate rides its belt; on the lower belt a closed gate stops the first one, and each
// crate stops against the one ahead (the crates are in the order they came, front first).
void DepotLevel::moveCrates(float dt)
{
    float lowerLimit = 1e9f; // where the next lower-belt crate's right edge must stay left of
    for (std::unique_ptr<Crate>& crate : crates)
    {
        sf::Vector2f at = crate->getPosition();
        const float before = at.x;
        at.x += crateSpeed * dt;
        if (at.y == lowerBeltTop)
        {
            if (!gateOpen && before + crateSize <= gatewayBox.left)
                at.x = std::min(at.x, gatewayBox.left - crateSize);
            at.x = std::min(at.x, lowerLimit - crateSize);
            lowerLimit = at.x;
        }
        crate->setPosition(at);
    }
}

void DepotLevel::update(float dt)
{
    spawnCrates();
    ++steps;
    guard->move(guardDirection * (guardSpeed * dt));
    const sf::Vector2f area = getWorldSize();
    guard->setPosition({std::clamp(guard->getPosition().x, 0.f, area.x - guardSize),
                        std::clamp(guard->getPosition().y, 0.f, area.y - guardSize)});
    moveCrates(dt);
    world.checkCollisions(); // the plate hears enter and exit; crates in the drop zone
    delivered += removeDelivered(world, crates);
    if (plate->isPressed())
        gateOpen = true;
    else if (isGatewayClear())
        gateOpen = false; // never closes on a crate or on the gatekeeper
}

bool DepotLevel::isGatewayClear() const
{
    const hitbox::Box doorway = hitbox::toBox(gateway->getCollisionBox());
    if (inGateway(doorway, hitbox::toBox(guard->getCollisionBox())))
        return false;
    for (const std::unique_ptr<Crate>& crate : crates)
        if (inGateway(doorway, hitbox::toBox(crate->getCollisionBox())))
            return false;
    return true;
}

void DepotLevel::render(sf::RenderTarget& target) const
{
    const sf::Color belt{70, 70, 78};
    drawBox(target, {0.f, upperBeltTop - 6.f, dropZoneBox.left + 20.f, crateSize + 12.f}, belt);
    drawBox(target, {0.f, lowerBeltTop - 6.f, dropZoneBox.left + 20.f, crateSize + 12.f}, belt);
    drawBox(target, dropZoneBox, {86, 180, 233, 90}, {86, 180, 233});
    // The plate is bluish green while pressed, grey when not.
    drawBox(target, plateBox,
            plate->isPressed() ? sf::Color{0, 158, 115} : sf::Color{120, 120, 120});
    // The gate: a solid bar when closed, only its frame when open.
    const sf::Color gate{225, 225, 235};
    drawBox(target, gatewayBox, gateOpen ? sf::Color::Transparent : gate, gate);
    for (const std::unique_ptr<Crate>& crate : crates)
        target.draw(*crate);
    target.draw(*guard);
}

void DepotLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    std::vector<const hitbox::GameObject*> objects{plate.get(), gateway.get(), dropZone.get(),
                                                   guard.get()};
    for (const std::unique_ptr<Crate>& crate : crates)
        objects.push_back(crate.get());
    // The panel: why the pair under the mouse (else the last pair that met or parted) does or
    // does not collide; the mouse on the gatekeeper explains it and the gateway.
    if (hitbox::pointInBox(hitbox::toVec2(mouse), hitbox::toBox(guard->getCollisionBox())))
    {
        const hitbox::Explanation why = hitbox::explain(*guard, *gateway);
        std::vector<std::string> lines{why.verdict};
        for (const std::string& step : why.steps)
            lines.push_back("  " + step);
        debug.panel(lines);
    }
    else
        hitbox::explainInPanel(debug, world, hitbox::toVec2(mouse), objects);
    for (const hitbox::GameObject* object : objects)
    {
        const hitbox::Box box = hitbox::toBox(object->getCollisionBox());
        hitbox::DebugState state = hitbox::DebugState::Free;
        for (const hitbox::GameObject* other : objects)
        {
            if (other == object)
                continue;
            const hitbox::Box otherBox = hitbox::toBox(other->getCollisionBox());
            if (hitbox::boxVsBox(box, otherBox))
                state = hitbox::DebugState::Overlapping;
            else if (touching(box, otherBox) && state == hitbox::DebugState::Free)
                state = hitbox::DebugState::Touching;
        }
        debug.objectShape(*object, world.getShape(*object), state, world.getShapes());
    }
}

std::string DepotLevel::getHelpText() const
{
    char text[160];
    std::snprintf(text, sizeof text, "delivered %d, gate %s, plate %s", delivered,
                  gateOpen ? "open" : "closed", plate->isPressed() ? "pressed" : "up");
    return text;
}

std::string DepotLevel::describeState() const
{
    return "step " + std::to_string(steps) + ": delivered " + std::to_string(delivered) + ", " +
           std::to_string(getCrateCount()) + " crates on the belts, gate " +
           (gateOpen ? "open" : "closed") + ", plate " + (plate->isPressed() ? "pressed" : "up");
}

std::vector<hitbox::PairEvent> DepotLevel::getContactEvents() const
{
    return world.getEvents();
}

const PressurePlate& DepotLevel::getPlate() const
{
    return *plate;
}

const hitbox::GameObject& DepotLevel::getGuard() const
{
    return *guard;
}

const hitbox::GameObject& DepotLevel::getGateway() const
{
    return *gateway;
}

int DepotLevel::getCrateCount() const
{
    return static_cast<int>(crates.size());
}

const Crate& DepotLevel::getCrate(int index) const
{
    return *crates.at(static_cast<std::size_t>(index));
}

int DepotLevel::getDelivered() const
{
    return delivered;
}

bool DepotLevel::isGateOpen() const
{
    return gateOpen;
}

const hitbox::World& DepotLevel::getWorld() const
{
    return world;
}
