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
const float pi = 3.14159265f;
} // namespace

void DebugRenderer::line(sf::Vector2f from, sf::Vector2f to, sf::Color color)
{
    // Each line is a thin quad (two triangles) rather than a 1-pixel sf::PrimitiveType::Lines
    // segment, so outlines stay visible on a lecture-hall projector.
    const sf::Vector2f along = to - from;
    const float length = std::sqrt(along.x * along.x + along.y * along.y);
    const sf::Vector2f side = length > 0.f
                                  ? sf::Vector2f(-along.y, along.x) * (lineWidth / 2.f / length)
                                  : sf::Vector2f(lineWidth / 2.f, 0.f);
    const sf::Vertex corners[4] = {
        {from - side, color}, {from + side, color}, {to + side, color}, {to - side, color}};
    for (int index : {0, 1, 2, 0, 2, 3})
        vertices.append(corners[index]);
}

void DebugRenderer::arrow(sf::Vector2f from, sf::Vector2f to, sf::Color color)
{
    line(from, to, color);
    const sf::Vector2f along = to - from;
    const float length = std::sqrt(along.x * along.x + along.y * along.y);
    if (length < 1e-3f)
        return;
    // Two short strokes at 30 degrees either side of the shaft make the head.
    const sf::Vector2f back = -along / length * std::fmin(8.f, length / 2.f);
    const sf::Vector2f side(-back.y * 0.5f, back.x * 0.5f);
    line(to, to + back + side, color);
    line(to, to + back - side, color);
}

void DebugRenderer::box(const sf::FloatRect& area, sf::Color color)
{
    const sf::FloatRect b = normalised(area);
    const sf::Vector2f topLeft(b.left, b.top);
    const sf::Vector2f topRight(b.left + b.width, b.top);
    const sf::Vector2f bottomRight(b.left + b.width, b.top + b.height);
    const sf::Vector2f bottomLeft(b.left, b.top + b.height);
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
        line(shape.center + shape.radius * sf::Vector2f(std::cos(a0), std::sin(a0)),
             shape.center + shape.radius * sf::Vector2f(std::cos(a1), std::sin(a1)), color);
    }
}

void DebugRenderer::cross(sf::Vector2f point, float size, sf::Color color)
{
    line(point - sf::Vector2f(size, size), point + sf::Vector2f(size, size), color);
    line(point - sf::Vector2f(size, -size), point + sf::Vector2f(size, -size), color);
}

void DebugRenderer::objectBox(const GameObject& object, bool touching)
{
    const sf::FloatRect area = object.getCollisionBox();
    box(area, touching ? touchingColor : freeColor);
    const sf::Vector2f middle = centerOf(area);
    arrow(middle, middle + object.getVelocity() * arrowSeconds, velocityColor);
}

void DebugRenderer::objectCircle(const GameObject& object, bool touching)
{
    const Circle shape = object.getBoundingCircle();
    circle(shape, touching ? touchingColor : freeColor);
    arrow(shape.center, shape.center + object.getVelocity() * arrowSeconds, velocityColor);
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

void DebugRenderer::clear()
{
    vertices.clear();
}

const sf::VertexArray& DebugRenderer::getVertices() const
{
    return vertices;
}

} // namespace hitbox
