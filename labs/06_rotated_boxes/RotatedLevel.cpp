#include "RotatedLevel.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Response.h"
#include "hitbox/sfml/Conversions.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/ConvexShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>

namespace
{
// An angle kept in [0, 360): a float that only grows loses its fraction (at 432,000 degrees
// a step of 6 degrees a frame is already rounded) and stops turning after about 42 hours.
float wrapDegrees(float degrees)
{
    const float wrapped = std::fmod(degrees, 360.f);
    return wrapped < 0.f ? wrapped + 360.f : wrapped;
}

// Pushing out of one shape can push into another: retry (used by task 4, so the exercise
// leaves it unused until then).
[[maybe_unused]] const int pushOutRounds = 4;

const sf::Color shapeColor{70, 110, 170};
const sf::Color heldColor{220, 180, 70};
const sf::Color overlapColor{200, 70, 80};
const sf::Color axisColor{200, 200, 210};
const sf::Color mtvColor{255, 90, 80};
const sf::Color separatingColor{110, 230, 140};

hitbox::Vec2 rotated(hitbox::Vec2 vector, float degrees)
{
    const float radians = degrees * hitbox::pi / 180.f;
    return {vector.x * std::cos(radians) - vector.y * std::sin(radians),
            vector.x * std::sin(radians) + vector.y * std::cos(radians)};
}

std::vector<Shape> labShapes()
{
    return {
        {{{560.f, 330.f}, {90.f, 40.f}, 25.f}, false}, // held first, over its neighbour
        {{{700.f, 360.f}, {70.f, 70.f}, 10.f}, false},
        {{{420.f, 470.f}, {60.f, 60.f}, 45.f}, false}, // apart, though the AABBs overlap
        {{{230.f, 190.f}, {110.f, 30.f}, -35.f}, false},
        {{{950.f, 200.f}, {40.f, 120.f}, 20.f}, false},
        {{{900.f, 500.f}, {90.f, 35.f}, 60.f}, true}, // the capsule
    };
}

void drawThickLine(sf::RenderTarget& target, hitbox::Vec2 from, hitbox::Vec2 to, float thickness,
                   sf::Color color)
{
    const hitbox::Vec2 along = to - from;
    sf::RectangleShape line({hitbox::length(along), thickness});
    line.setOrigin({0.f, thickness / 2.f});
    line.setPosition(hitbox::toSfml(from));
    hitbox::setRotationDegrees(line, std::atan2(along.y, along.x) * 180.f / hitbox::pi);
    line.setFillColor(color);
    target.draw(line);
}

// The axis-aligned box around a shape: what an AABB test would compare.
hitbox::Box boundsOf(const Shape& shape)
{
    if (shape.isCapsule)
    {
        const hitbox::Capsule capsule = shape.capsule();
        const float left = std::fmin(capsule.start.x, capsule.end.x) - capsule.radius;
        const float top = std::fmin(capsule.start.y, capsule.end.y) - capsule.radius;
        return {left, top, std::fabs(capsule.end.x - capsule.start.x) + 2.f * capsule.radius,
                std::fabs(capsule.end.y - capsule.start.y) + 2.f * capsule.radius};
    }
    const hitbox::Polygon polygon = shape.polygon();
    hitbox::Vec2 low = polygon.points[0];
    hitbox::Vec2 high = polygon.points[0];
    for (const hitbox::Vec2& point : polygon.points)
    {
        low = {std::fmin(low.x, point.x), std::fmin(low.y, point.y)};
        high = {std::fmax(high.x, point.x), std::fmax(high.y, point.y)};
    }
    return {low, high - low};
}

void drawOutline(sf::RenderTarget& target, const hitbox::Polygon& polygon, sf::Color color)
{
    sf::ConvexShape drawn(polygon.points.size());
    for (std::size_t p = 0; p < polygon.points.size(); ++p)
        drawn.setPoint(p, hitbox::toSfml(polygon.points[p]));
    drawn.setFillColor(sf::Color::Transparent);
    drawn.setOutlineColor(color);
    drawn.setOutlineThickness(2.f);
    target.draw(drawn);
}

bool pointInShape(hitbox::Vec2 point, const Shape& shape)
{
    if (shape.isCapsule)
    {
        const hitbox::Capsule capsule = shape.capsule();
        const hitbox::Vec2 closest =
            hitbox::closestPointOnSegment(point, capsule.start, capsule.end);
        return hitbox::length(point - closest) < capsule.radius;
    }
    return hitbox::pointInPolygon(point, shape.polygon());
}
} // namespace

hitbox::Polygon Shape::polygon() const
{
    return hitbox::toPolygon(body);
}

hitbox::Capsule Shape::capsule() const
{
    const hitbox::Vec2 half = rotated({body.halfSize.x, 0.f}, body.angleDegrees);
    return {body.center - half, body.center + half, body.halfSize.y};
}

RotatedLevel::RotatedLevel() : RotatedLevel(labShapes()) {}

RotatedLevel::RotatedLevel(std::vector<Shape> startShapes)
    : shapes(std::move(startShapes)), overlapping(shapes.size(), false)
{
    update(0.f); // so the pairs are known before the first step
}

const std::vector<Shape>& RotatedLevel::getShapes() const
{
    return shapes;
}

std::size_t RotatedLevel::getHeld() const
{
    return held;
}

const std::vector<PairView>& RotatedLevel::getPairs() const
{
    return pairs;
}

bool RotatedLevel::isOverlapping(std::size_t i) const
{
    return i < overlapping.size() && overlapping[i];
}

void RotatedLevel::handleInput(const hitbox::Input& input, float)
{
    const hitbox::Vec2 mouse = hitbox::toVec2(input.getMousePosition());
    if (input.isLeftMousePressed())
    {
        // Pick up the shape under the mouse (the held one first, so it can be re-grabbed).
        for (std::size_t i = 0; i < shapes.size(); ++i)
        {
            const std::size_t candidate = (held + i) % shapes.size();
            if (pointInShape(mouse, shapes[candidate]))
            {
                held = candidate;
                dragging = true;
                grabOffset = shapes[held].body.center - mouse;
                break;
            }
        }
    }
    if (!input.isLeftMouseDown())
        dragging = false;
    if (dragging)
        shapes[held].body.center = mouse + grabOffset;
    if (input.isPressed(sf::Keyboard::Key::Tab) && !shapes.empty())
        held = (held + 1) % shapes.size();

    if (input.getMouseWheel() != 0.f)
        turnHeld(input.getMouseWheel());
    if (input.isPressed(sf::Keyboard::Key::F))
        frameworkSat = !frameworkSat;
    if (input.isPressed(sf::Keyboard::Key::Space))
        pushHeldOut();
}

void RotatedLevel::turnHeld(float notches)
{
    // BEGIN TASK 3: the mouse wheel turns the held shape
    shapes[held].body.angleDegrees += notches * degreesPerNotch;
    // STARTER TASK 3
    // static_cast<void>(notches); // (only keeps the compiler quiet: delete it)
    // END TASK 3
}

void RotatedLevel::setFrameworkSat(bool on)
{
    frameworkSat = on;
}

bool RotatedLevel::usesFrameworkSat() const
{
    return frameworkSat;
}

PairView RotatedLevel::testPair(std::size_t heldIndex, std::size_t otherIndex) const
{
    const Shape& a = shapes[heldIndex];
    const Shape& b = shapes[otherIndex];
    PairView view;
    view.other = otherIndex;
    view.boundsOverlap = hitbox::boxVsBox(boundsOf(a), boundsOf(b));
    if (!a.isCapsule && !b.isCapsule && frameworkSat)
    {
        // Two boxes, the framework's answer (no shadows to draw: those come from Sat.cpp).
        const hitbox::AxisReport report = hitbox::findSeparatingAxis(a.polygon(), b.polygon());
        view.overlapping = !report.separated;
        view.axis = report.axis;
        view.gap = report.gap;
        return view;
    }
    if (!a.isCapsule && !b.isCapsule)
    {
        // Two boxes: your separating axis test (Sat.cpp).
        const SatResult sat = separatingAxisTest(a.polygon(), b.polygon());
        view.overlapping = !sat.separated;
        view.axis = sat.axis;
        view.gap = sat.gap;
        view.hasShadows = sat.axis != hitbox::Vec2{};
        view.heldShadow = projectOnto(a.polygon(), sat.axis);
        view.otherShadow = projectOnto(b.polygon(), sat.axis);
        return view;
    }
    // The capsule: the framework's test (its round ends need extra axes, see Capsule.h).
    hitbox::Contact contact;
    if (a.isCapsule)
        contact = hitbox::capsuleVsPolygon(a.capsule(), b.polygon());
    else
    {
        contact = hitbox::capsuleVsPolygon(b.capsule(), a.polygon());
        contact.normal = -contact.normal; // seen from the box
    }
    view.overlapping = contact.hit;
    view.axis = contact.normal;
    view.gap = -contact.depth;
    return view;
}

void RotatedLevel::setSpin(float degreesPerSecond)
{
    spinDegreesPerSecond = degreesPerSecond;
}

void RotatedLevel::update(float dt)
{
    if (!shapes.empty())
        shapes[held].body.angleDegrees =
            wrapDegrees(shapes[held].body.angleDegrees + spinDegreesPerSecond * dt);
    pairs.clear();
    overlapping.assign(shapes.size(), false);
    for (std::size_t i = 0; i < shapes.size(); ++i)
        for (std::size_t j = i + 1; j < shapes.size(); ++j)
        {
            if (shapes[i].isCapsule && shapes[j].isCapsule)
                continue; // one capsule in this lab
            const PairView view = testPair(i, j);
            if (view.overlapping)
                overlapping[i] = overlapping[j] = true;
        }
    for (std::size_t other = 0; other < shapes.size(); ++other)
        if (other != held)
            pairs.push_back(testPair(held, other));
}

void RotatedLevel::pushHeldOut()
{
    // BEGIN TASK 4: push the held shape out along the minimum translation vector
    for (int round = 0; round < pushOutRounds; ++round)
    {
        bool moved = false;
        for (std::size_t other = 0; other < shapes.size(); ++other)
        {
            if (other == held)
                continue;
            const PairView view = testPair(held, other);
            if (!view.overlapping)
                continue;
            // The MTV, rounded outward (Response.h): exactly axis * depth can stay inside.
            const hitbox::Contact contact{true, view.axis, -view.gap, shapes[held].body.center};
            shapes[held].body.center += hitbox::pushOutOffset(contact);
            moved = true;
        }
        if (!moved)
            break;
    }
    // END TASK 4
    update(0.f);
}

const PairView* RotatedLevel::getNearestPair() const
{
    const PairView* nearest = nullptr;
    float nearestDistance = 0.f;
    for (const PairView& view : pairs)
    {
        const float distance =
            hitbox::length(shapes[view.other].body.center - shapes[held].body.center);
        if (!nearest || distance < nearestDistance)
        {
            nearest = &view;
            nearestDistance = distance;
        }
    }
    return nearest;
}

void RotatedLevel::render(sf::RenderTarget& target) const
{
    for (std::size_t i = 0; i < shapes.size(); ++i)
    {
        const Shape& shape = shapes[i];
        sf::Color fill = i == held ? heldColor : shapeColor;
        if (overlapping[i])
            fill = i == held ? sf::Color(240, 120, 60) : overlapColor;
        if (shape.isCapsule)
        {
            const hitbox::Capsule capsule = shape.capsule();
            drawThickLine(target, capsule.start, capsule.end, 2.f * capsule.radius, fill);
            for (const hitbox::Vec2& end : {capsule.start, capsule.end})
            {
                sf::CircleShape cap(capsule.radius, 32);
                cap.setOrigin({capsule.radius, capsule.radius});
                cap.setPosition(hitbox::toSfml(end));
                cap.setFillColor(fill);
                target.draw(cap);
            }
            continue;
        }
        const hitbox::Polygon polygon = shape.polygon();
        sf::ConvexShape drawn(polygon.points.size());
        for (std::size_t p = 0; p < polygon.points.size(); ++p)
            drawn.setPoint(p, hitbox::toSfml(polygon.points[p]));
        drawn.setFillColor(fill);
        target.draw(drawn);
    }

    const PairView* nearest = getNearestPair();
    if (nearest && nearest->hasShadows)
    {
        // The axis, drawn beside the two shapes, with each shape's shadow on it.
        const hitbox::Vec2 heldCenter = shapes[held].body.center;
        const hitbox::Vec2 otherCenter = shapes[nearest->other].body.center;
        const hitbox::Vec2 middle = (heldCenter + otherCenter) / 2.f;
        const hitbox::Vec2 across = hitbox::perpendicular(nearest->axis);
        const hitbox::Vec2 anchor = middle + across * 170.f;
        const float anchorAlong = hitbox::dot(anchor, nearest->axis);
        auto onAxis = [&](float along) { return anchor + nearest->axis * (along - anchorAlong); };
        drawThickLine(target, onAxis(anchorAlong - 400.f), onAxis(anchorAlong + 400.f), 1.5f,
                      axisColor);
        drawThickLine(target, onAxis(nearest->otherShadow.min), onAxis(nearest->otherShadow.max),
                      7.f, shapeColor);
        drawThickLine(target, onAxis(nearest->heldShadow.min) + across * 8.f,
                      onAxis(nearest->heldShadow.max) + across * 8.f, 7.f, heldColor);
    }
    for (const PairView& view : pairs)
    {
        // Apart although their axis-aligned boxes overlap: the case an AABB test gets
        // wrong. The separating line sits at right angles to the axis, in the middle of the gap.
        if (view.overlapping || !view.boundsOverlap || !view.hasShadows)
            continue;
        const hitbox::Vec2 middle =
            (shapes[held].body.center + shapes[view.other].body.center) / 2.f;
        const float gapMiddle = (std::fmax(view.heldShadow.min, view.otherShadow.min) +
                                 std::fmin(view.heldShadow.max, view.otherShadow.max)) /
                                2.f;
        const hitbox::Vec2 through =
            middle + view.axis * (gapMiddle - hitbox::dot(middle, view.axis));
        const hitbox::Vec2 across = hitbox::perpendicular(view.axis);
        drawThickLine(target, through - across * 150.f, through + across * 150.f, 3.f,
                      separatingColor);
    }
    // The MTV of every overlap with the held shape: the shortest way out.
    for (const PairView& view : pairs)
        if (view.overlapping)
        {
            const hitbox::Vec2 from = shapes[held].body.center;
            const hitbox::Vec2 to = from + view.axis * std::fmax(-view.gap, 4.f);
            drawThickLine(target, from, to, 4.f, mtvColor);
            if (!shapes[held].isCapsule)
            {
                // Where the held shape would be after the push: exactly touching.
                hitbox::Polygon pushed = shapes[held].polygon();
                for (hitbox::Vec2& point : pushed.points)
                    point += view.axis * -view.gap;
                drawOutline(target, pushed, sf::Color(255, 255, 255, 150));
            }
            sf::CircleShape head(7.f, 3);
            head.setOrigin({7.f, 7.f});
            head.setPosition(hitbox::toSfml(to));
            hitbox::setRotationDegrees(
                head, std::atan2(view.axis.y, view.axis.x) * 180.f / hitbox::pi + 90.f);
            head.setFillColor(mtvColor);
            target.draw(head);
        }

    std::string status = "held shape: ";
    if (nearest && nearest->overlapping)
        status += "OVERLAPS - red arrow: the minimum translation vector (" +
                  std::to_string(std::lround(-nearest->gap)) + " px). Space pushes it out.";
    else if (nearest)
        status += "apart from its nearest neighbour (gap " +
                  std::to_string(std::lround(nearest->gap)) + " px)";
    sf::Text text = hitbox::makeText(font.get(), status, 20);
    text.setFillColor(sf::Color::White);
    text.setPosition({16.f, 10.f});
    target.draw(text);
    sf::Text legend =
        hitbox::makeText(font.get(),
                         "bars: both shadows on the axis SAT chose for the nearest shape (yellow: "
                         "held)   green line: a separating line where the AABBs overlap",
                         16);
    legend.setFillColor(sf::Color(190, 190, 200));
    legend.setPosition({16.f, 38.f});
    target.draw(legend);
}

void RotatedLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    // The axis-aligned boxes around the shapes: they overlap far more often than the shapes.
    for (std::size_t i = 0; i < shapes.size(); ++i)
    {
        hitbox::Polygon outline;
        if (shapes[i].isCapsule)
        {
            const hitbox::Capsule capsule = shapes[i].capsule();
            debug.circle({capsule.start, capsule.radius}, hitbox::DebugRenderer::hintColor);
            debug.circle({capsule.end, capsule.radius}, hitbox::DebugRenderer::hintColor);
            debug.line(capsule.start, capsule.end, hitbox::DebugRenderer::hintColor);
            debug.box(boundsOf(shapes[i]), hitbox::DebugRenderer::hintColor);
            continue;
        }
        debug.box(boundsOf(shapes[i]), hitbox::DebugRenderer::hintColor);
        outline = shapes[i].polygon();
        const sf::Color color = overlapping[i] ? hitbox::DebugRenderer::overlappingColor
                                               : hitbox::DebugRenderer::freeColor;
        for (std::size_t p = 0; p < outline.points.size(); ++p)
            debug.line(outline.points[p], outline.points[(p + 1) % outline.points.size()], color);
    }
}

std::string RotatedLevel::getHelpText() const
{
    return "Drag a shape   Wheel turn it   Space push out (MTV)   Tab next shape   F framework's "
           "SAT";
}

std::string RotatedLevel::describeState() const
{
    int count = 0;
    for (bool overlaps : overlapping)
        count += overlaps ? 1 : 0;
    return std::to_string(count) + " of " + std::to_string(shapes.size()) +
           " shapes overlap; held shape " + std::to_string(held) + " at " +
           std::to_string(std::lround(shapes[held].body.angleDegrees)) + " degrees" +
           (frameworkSat ? " (framework's SAT)" : "");
}

using RotatedSnapshot = hitbox::WholeLevelCopy<RotatedLevel>; // Level.h: a copy of the whole level

std::unique_ptr<hitbox::LevelState> RotatedLevel::saveState() const
{
    const std::size_t held = sizeof(RotatedSnapshot) + shapes.size() * sizeof(Shape) +
                             pairs.size() * sizeof(PairView) + overlapping.size() / 8;
    return std::make_unique<RotatedSnapshot>(*this, held);
}

void RotatedLevel::restoreState(const hitbox::LevelState& state)
{
    *this = static_cast<const RotatedSnapshot&>(state).level;
}
