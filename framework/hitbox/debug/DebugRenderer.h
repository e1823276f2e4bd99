// DebugRenderer.h - outlines of collision shapes, velocity arrows and contact normals.
//
// Levels describe what to draw in renderDebug(); the renderer collects every line (a 2-pixel
// wide quad) into one vertex array and draws it with a single draw call. Building the lines needs
// no window, so tests can check what would be drawn.
#pragma once

#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <string>
#include <vector>

class GameObject;
namespace sf
{
class RenderTarget;
}

namespace hitbox
{

class DebugRenderer
{
public:
    // The colours every program uses, so students learn them once.
    static const sf::Color freeColor;     // a collider touching nothing
    static const sf::Color touchingColor; // a collider touching something this step
    static const sf::Color velocityColor; // velocity arrows
    static const sf::Color normalColor;   // contact normals
    static const sf::Color hintColor;     // anything else: rays, swept areas, grids

    // A line 2 pixels wide, in world coordinates (one of zero length shows nothing).
    void line(Vec2 from, Vec2 to, sf::Color color);
    // A line with an arrowhead at `to`.
    void arrow(Vec2 from, Vec2 to, sf::Color color);
    // The outline of `box` (a negative size is drawn as the box it spans).
    void box(const Box& box, sf::Color color);
    // The outline of `circle`.
    void circle(const Circle& circle, sf::Color color);
    // An x of `size` pixels across, centred on `point`.
    void cross(Vec2 point, float size, sf::Color color);

    // An object's world collision box (or bounding circle) and its velocity arrow, which
    // shows where the object will be in a quarter of a second.
    void objectBox(const GameObject& object, bool touching);
    void objectCircle(const GameObject& object, bool touching);
    // A contact point and its normal, 24 pixels long.
    void contact(const Contact& contact);

    // Lines of text for the panel in the top-left corner of the window while F1 is on (the
    // window draws them with its font; e.g. explain's answer). Each call adds lines.
    void panel(const std::vector<std::string>& lines);
    [[nodiscard]] const std::vector<std::string>& getPanel() const;

    // Draw everything collected, in one call, then keep it (call clear() to start again).
    void draw(sf::RenderTarget& target) const;
    // Forgets everything collected.
    void clear();
    // Everything collected so far (two triangles a line): tests read it without a window.
    const sf::VertexArray& getVertices() const;

private:
    sf::VertexArray vertices{sf::PrimitiveType::Triangles};
    std::vector<std::string> panelLines;
};

} // namespace hitbox
