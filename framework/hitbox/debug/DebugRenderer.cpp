#include "hitbox/debug/DebugRenderer.h"

#include "hitbox/objects/GameObject.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RenderStates.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace hitbox
{

// Okabe-Ito's eight colours (https://jfly.uni-koeln.de/color/) on the windows' dark
// background: the five bright ones, and a neutral grey for hints.
const sf::Color DebugRenderer::freeColor{86, 180, 233};      // sky blue #56B4E9
const sf::Color DebugRenderer::touchingColor{240, 228, 66};  // yellow #F0E442
const sf::Color DebugRenderer::overlappingColor{213, 94, 0}; // vermillion #D55E00
const sf::Color DebugRenderer::velocityColor{204, 121, 167}; // reddish purple #CC79A7
const sf::Color DebugRenderer::normalColor{0, 158, 115};     // bluish green #009E73
const sf::Color DebugRenderer::hintColor{150, 150, 160};     // grey
const sf::Color DebugRenderer::backgroundColor{18, 20, 28};  // near-black, slightly blue
const char* const DebugRenderer::legend = "Debug: solid free, dashed touching, hatched overlapping";

namespace
{
const float arrowSeconds = 0.25f; // velocity arrows show a quarter of a second of motion
const float normalLength = 24.f;
const float lineWidth = 2.f;     // pixels
const float hairlineWidth = 1.f; // pixels at 1:1
const float dashLength = 6.f;    // touching: 6 px drawn, 4 px gap
const float dashGap = 4.f;
const float hatchSpacing = 7.f; // overlapping: a 45-degree stripe every 7 px
const int circleSegments = 32;

Vec2 onCircle(const Circle& shape, int segment)
{
    const float angle = 2.f * pi * static_cast<float>(segment) / circleSegments;
    return shape.center + shape.radius * Vec2(std::cos(angle), std::sin(angle));
}
} // namespace

sf::Color DebugRenderer::colorOf(DebugState state)
{
    switch (state)
    {
    case DebugState::Free:
        return freeColor;
    case DebugState::Touching:
        return touchingColor;
    case DebugState::Overlapping:
        return overlappingColor;
    }
    return hintColor;
}

void DebugRenderer::line(Vec2 from, Vec2 to, sf::Color color)
{
    // Each line is a thin quad (two triangles) rather than a 1-pixel sf::PrimitiveType::Lines
    // segment, so outlines stay visible on a lecture-hall projector.
    quad(from, to, lineWidth, color);
}

void DebugRenderer::hairline(Vec2 from, Vec2 to, sf::Color color)
{
    // At least one screen pixel: thinner, a line misses the pixel centres and drops out.
    quad(from, to, std::max(hairlineWidth, screenPixel), color);
}

void DebugRenderer::setScreenPixel(float worldUnits)
{
    if (worldUnits > 0.f && std::isfinite(worldUnits))
        screenPixel = worldUnits;
}

void DebugRenderer::quad(Vec2 from, Vec2 to, float width, sf::Color color)
{
    const Vec2 along = to - from;
    const float length = std::sqrt(along.x * along.x + along.y * along.y);
    const Vec2 side =
        length > 0.f ? Vec2(-along.y, along.x) * (width / 2.f / length) : Vec2(width / 2.f, 0.f);
    const sf::Vertex corners[4] = {{toSfml(from - side), color},
                                   {toSfml(from + side), color},
                                   {toSfml(to + side), color},
                                   {toSfml(to - side), color}};
    for (int index : {0, 1, 2, 0, 2, 3})
        vertices.append(corners[index]);
    opaque = opaque && color.a == 255;
}

void DebugRenderer::arrow(Vec2 from, Vec2 to, sf::Color color)
{
    line(from, to, color);
    const Vec2 along = to - from;
    const float length = std::sqrt(along.x * along.x + along.y * along.y);
    if (length < 1e-3f)
        return;
    // Two short strokes at 30 degrees either side of the shaft make the head.
    const Vec2 back = -along / length * std::fmin(8.f, length / 2.f);
    const Vec2 side(-back.y * 0.5f, back.x * 0.5f);
    line(to, to + back + side, color);
    line(to, to + back - side, color);
}

void DebugRenderer::box(const Box& area, sf::Color color)
{
    const Box b = normalised(area);
    const Vec2 topLeft(b.left, b.top);
    const Vec2 topRight(b.left + b.width, b.top);
    const Vec2 bottomRight(b.left + b.width, b.top + b.height);
    const Vec2 bottomLeft(b.left, b.top + b.height);
    line(topLeft, topRight, color);
    line(topRight, bottomRight, color);
    line(bottomRight, bottomLeft, color);
    line(bottomLeft, topLeft, color);
}

void DebugRenderer::circle(const Circle& shape, sf::Color color)
{
    for (int i = 0; i < circleSegments; ++i)
        line(onCircle(shape, i), onCircle(shape, i + 1), color);
}

void DebugRenderer::dashed(Vec2 from, Vec2 to, sf::Color color)
{
    const Vec2 along = to - from;
    const float length = std::sqrt(along.x * along.x + along.y * along.y);
    if (!(length > 0.f))
        return;
    const Vec2 unit = along / length;
    for (float start = 0.f; start < length; start += dashLength + dashGap)
        line(from + unit * start, from + unit * std::fmin(start + dashLength, length), color);
}

void DebugRenderer::box(const Box& area, DebugState state)
{
    const sf::Color color = colorOf(state);
    const Box b = normalised(area);
    const Vec2 corners[4] = {{b.left, b.top},
                             {b.left + b.width, b.top},
                             {b.left + b.width, b.top + b.height},
                             {b.left, b.top + b.height}};
    for (int i = 0; i < 4; ++i)
    {
        if (state == DebugState::Touching)
            dashed(corners[i], corners[(i + 1) % 4], color);
        else
            line(corners[i], corners[(i + 1) % 4], color);
    }
    if (state != DebugState::Overlapping || !(b.width > 0.f) || !(b.height > 0.f))
        return;
    // Hatching: the lines x + y = c that cross the box, each clipped to it.
    const float first = b.left + b.top;
    const float last = b.left + b.width + b.top + b.height;
    const int stripes = static_cast<int>(std::fmin((last - first) / hatchSpacing, 2000.f));
    for (int k = 1; k <= stripes; ++k)
    {
        const float c = first + hatchSpacing * static_cast<float>(k);
        const float xLow = std::fmax(b.left, c - (b.top + b.height));
        const float xHigh = std::fmin(b.left + b.width, c - b.top);
        if (xLow < xHigh)
            line({xLow, c - xLow}, {xHigh, c - xHigh}, color);
    }
}

void DebugRenderer::circle(const Circle& shape, DebugState state)
{
    const sf::Color color = colorOf(state);
    for (int i = 0; i < circleSegments; ++i)
    {
        // Dashed: every other one of the 32 arcs.
        if (state != DebugState::Touching || i % 2 == 0)
            line(onCircle(shape, i), onCircle(shape, i + 1), color);
    }
    if (state != DebugState::Overlapping || !(shape.radius > 0.f))
        return;
    // Hatching: 45-degree chords every hatchSpacing pixels.
    const Vec2 across(std::sqrt(0.5f), -std::sqrt(0.5f)); // steps between chords
    const Vec2 along(std::sqrt(0.5f), std::sqrt(0.5f));   // direction of each chord
    const int stripes = static_cast<int>(std::fmin(shape.radius / hatchSpacing, 1000.f));
    for (int k = -stripes; k <= stripes; ++k)
    {
        const float offset = hatchSpacing * static_cast<float>(k);
        const float half = std::sqrt(std::fmax(0.f, shape.radius * shape.radius - offset * offset));
        const Vec2 middle = shape.center + across * offset;
        if (half > 0.f)
            line(middle - along * half, middle + along * half, color);
    }
}

void DebugRenderer::polygon(const Polygon& shape, sf::Color color)
{
    const std::size_t count = shape.points.size();
    for (std::size_t i = 0; count >= 2 && i < count; ++i)
        line(shape.points[i], shape.points[(i + 1) % count], color);
}

void DebugRenderer::polygon(const Polygon& shape, DebugState state)
{
    const sf::Color color = colorOf(state);
    const std::size_t count = shape.points.size();
    for (std::size_t i = 0; count >= 2 && i < count; ++i)
    {
        if (state == DebugState::Touching)
            dashed(shape.points[i], shape.points[(i + 1) % count], color);
        else
            line(shape.points[i], shape.points[(i + 1) % count], color);
    }
    if (state != DebugState::Overlapping || count < 3)
        return;
    // Hatching as for a box: the lines x + y = c, each clipped to the (convex) polygon by
    // the lowest and highest x where it crosses an edge.
    float first = shape.points[0].x + shape.points[0].y;
    float last = first;
    for (const Vec2 point : shape.points)
    {
        first = std::fmin(first, point.x + point.y);
        last = std::fmax(last, point.x + point.y);
    }
    const int stripes = static_cast<int>(std::fmin((last - first) / hatchSpacing, 2000.f));
    for (int k = 1; k <= stripes; ++k)
    {
        const float c = first + hatchSpacing * static_cast<float>(k);
        float xLow = std::numeric_limits<float>::infinity();
        float xHigh = -xLow;
        for (std::size_t i = 0; i < count; ++i)
        {
            const Vec2 a = shape.points[i];
            const Vec2 b = shape.points[(i + 1) % count];
            const float da = a.x + a.y - c;
            const float db = b.x + b.y - c;
            if ((da < 0.f) == (db < 0.f) || da == db)
                continue; // this edge does not cross the line
            const float x = a.x + (b.x - a.x) * (da / (da - db));
            xLow = std::fmin(xLow, x);
            xHigh = std::fmax(xHigh, x);
        }
        if (xLow < xHigh)
            line({xLow, c - xLow}, {xHigh, c - xHigh}, color);
    }
}

void DebugRenderer::cross(Vec2 point, float size, sf::Color color)
{
    line(point - Vec2(size, size), point + Vec2(size, size), color);
    line(point - Vec2(size, -size), point + Vec2(size, -size), color);
}

void DebugRenderer::objectBox(const GameObject& object, DebugState state)
{
    const Box area = toBox(object.getCollisionBox());
    box(area, state);
    const Vec2 middle = centerOf(area);
    arrow(middle, middle + toVec2(object.getVelocity()) * arrowSeconds, velocityColor);
}

void DebugRenderer::objectCircle(const GameObject& object, DebugState state)
{
    const Circle shape = object.getBoundingCircle();
    circle(shape, state);
    arrow(shape.center, shape.center + toVec2(object.getVelocity()) * arrowSeconds, velocityColor);
}

void DebugRenderer::objectShape(const GameObject& object, ShapeKind kind, DebugState state,
                                const ShapeTable& shapes)
{
    polygon(shapes.outline(object, kind), state);
    const Vec2 middle = centerOf(shapes.bounds(object, kind));
    arrow(middle, middle + toVec2(object.getVelocity()) * arrowSeconds, velocityColor);
}

void DebugRenderer::objectBox(const GameObject& object, bool colliding)
{
    objectBox(object, colliding ? DebugState::Overlapping : DebugState::Free);
}

void DebugRenderer::objectCircle(const GameObject& object, bool colliding)
{
    objectCircle(object, colliding ? DebugState::Overlapping : DebugState::Free);
}

void DebugRenderer::contact(const Contact& found)
{
    if (!found.hit)
        return;
    cross(found.point, 4.f, normalColor);
    arrow(found.point, found.point + found.normal * normalLength, normalColor);
}

void DebugRenderer::draw(sf::RenderTarget& target) const
{
    // Opaque lines skip blending: with lab 8's grid lines at 10,000 balls (2 units wide every 10
    // then), Xvfb's software renderer drew about 6 % more frames a second when it need not read
    // those pixels back (docs/performance.md, "Sixth round").
    if (vertices.getVertexCount() > 0)
        drawTriangles(target, &vertices[0], vertices.getVertexCount(), renderStatesFor(opaque));
}

bool DebugRenderer::isOpaque() const
{
    return opaque;
}

void DebugRenderer::panel(const std::vector<std::string>& lines)
{
    panelLines.insert(panelLines.end(), lines.begin(), lines.end());
}

const std::vector<std::string>& DebugRenderer::getPanel() const
{
    return panelLines;
}

void DebugRenderer::clear()
{
    vertices.clear();
    opaque = true;
    panelLines.clear();
}

const sf::VertexArray& DebugRenderer::getVertices() const
{
    return vertices;
}

} // namespace hitbox
