#include "hitbox/debug/DebugRenderer.h"

#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics/RenderTarget.hpp>

#include <cmath>

namespace hitbox
{

const sf::Color DebugRenderer::freeColor{80, 255, 120};
const sf::Color DebugRenderer::touchingColor{255, 70, 70};
const sf::Color DebugRenderer::velocityColor{255, 220, 60};
const sf::Color DebugRenderer::normalColor{80, 200, 255};
const sf::Color DebugRenderer::hintColor{200, 120, 255};

namespace
{
const float arrowSeconds = 0.25f; // velocity arrows show a quarter of a second of motion
const float normalLength = 24.f;
const float lineWidth = 2.f; // pixels
} // namespace

void DebugRenderer::line(Vec2 from, Vec2 to, sf::Color color)
{
    // Each line is a thin quad (two triangles) rather than a 1-pixel sf::PrimitiveType::Lines
    // segment, so outlines stay visible on a lecture-hall projector.
    const Vec2 along = to - from;
    const float length = std::sqrt(along.x * along.x + along.y * along.y);
    const Vec2 side = length > 0.f ? Vec2(-along.y, along.x) * (lineWidth / 2.f / length)
                                   : Vec2(lineWidth / 2.f, 0.f);
    const sf::Vertex corners[4] = {{toSfml(from - side), color},
                                   {toSfml(from + side), color},
                                   {toSfml(to + side), color},
                                   {toSfml(to - side), color}};
    for (int index : {0, 1, 2, 0, 2, 3})
        vertices.append(corners[index]);
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
    const int segments = 32;
    for (int i = 0; i < segments; ++i)
    {
        const float a0 = 2.f * pi * static_cast<float>(i) / segments;
        const float a1 = 2.f * pi * static_cast<float>(i + 1) / segments;
        line(shape.center + shape.radius * Vec2(std::cos(a0), std::sin(a0)),
             shape.center + shape.radius * Vec2(std::cos(a1), std::sin(a1)), color);
    }
}

void DebugRenderer::cross(Vec2 point, float size, sf::Color color)
{
    line(point - Vec2(size, size), point + Vec2(size, size), color);
    line(point - Vec2(size, -size), point + Vec2(size, -size), color);
}

void DebugRenderer::objectBox(const GameObject& object, bool touching)
{
    const Box area = toBox(object.getCollisionBox());
    box(area, touching ? touchingColor : freeColor);
    const Vec2 middle = centerOf(area);
    arrow(middle, middle + toVec2(object.getVelocity()) * arrowSeconds, velocityColor);
}

void DebugRenderer::objectCircle(const GameObject& object, bool touching)
{
    const Circle shape = object.getBoundingCircle();
    circle(shape, touching ? touchingColor : freeColor);
    arrow(shape.center, shape.center + toVec2(object.getVelocity()) * arrowSeconds, velocityColor);
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
    target.draw(vertices);
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
    panelLines.clear();
}

const sf::VertexArray& DebugRenderer::getVertices() const
{
    return vertices;
}

} // namespace hitbox
