// DebugRenderer.h - outlines of collision shapes, velocity arrows and contact normals.
//
// Levels describe what to draw in renderDebug(); the renderer collects every line (a 2-pixel
// wide quad) into one vertex array and draws it in one call, or a few for thousands of lines
// (drawTriangles in sfml/Graphics.h). Building the lines needs no window, so tests can check
// what would be drawn.
#pragma once

#include "hitbox/geometry/Polygon.h"
#include "hitbox/objects/ShapeTable.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <string>
#include <vector>

namespace sf
{
class RenderTarget;
}

namespace hitbox
{
class GameObject;

// What a collision shape is doing this step. Each state has its own colour AND its own line
// style, so colour is never the only cue (red/green colour blindness affects about 1 man in
// 12): free - solid outline; touching - dashed outline; overlapping - outline and hatching.
enum class DebugState
{
    Free,       // shares no edge and no area with anything
    Touching,   // edges meet, no shared area (not a collision: Hitbox's edge rule)
    Overlapping // shares area with something: a collision
};

class DebugRenderer
{
public:
    // The colours every program uses, so students learn them once: the Okabe-Ito palette
    // (Okabe & Ito, "Color Universal Design", 2008), told apart with every common colour
    // vision deficiency (scripts/check-palette.py simulates three and checks).
    static const sf::Color freeColor;        // sky blue: a collider touching nothing
    static const sf::Color touchingColor;    // yellow: edges meet, no shared area
    static const sf::Color overlappingColor; // vermillion: shares area (collides) this step
    static const sf::Color velocityColor;    // reddish purple: velocity arrows
    static const sf::Color normalColor;      // bluish green: contact normals
    static const sf::Color hintColor;        // grey: anything else (rays, swept areas, grids)
    // What the windows clear to (and Pong's text strips): the dark the palette is checked
    // against.
    static const sf::Color backgroundColor;
    // What the cues mean, for every program's help line while F1 is on.
    static const char* const legend;

    // A state's colour (freeColor, touchingColor or overlappingColor).
    [[nodiscard]] static sf::Color colorOf(DebugState state);

    // A line 2 pixels wide, in world coordinates (one of zero length shows nothing).
    void line(Vec2 from, Vec2 to, sf::Color color);
    // The same 1 unit wide, and never less than one screen pixel (setScreenPixel): for
    // patterns so fine (a grid of small cells) that 2-unit lines would cover much of the
    // picture and hide what lies under them.
    void hairline(Vec2 from, Vec2 to, sf::Color color);
    // How many world units one screen pixel spans: 1 at 1:1 (the default), more when the
    // window is shrunk to fit the screen. 0 or less, infinite or NaN: ignored.
    void setScreenPixel(float worldUnits);
    // A line with an arrowhead at `to`.
    void arrow(Vec2 from, Vec2 to, sf::Color color);
    // The outline of `box` (a negative size is drawn as the box it spans).
    void box(const Box& box, sf::Color color);
    // The outline of `circle`.
    void circle(const Circle& circle, sf::Color color);
    // A box or circle drawn in its state's colour and line style (solid, dashed, hatched).
    void box(const Box& box, DebugState state);
    void circle(const Circle& circle, DebugState state);
    // The closed outline of `polygon` (its points in order; fewer than two draw nothing), and
    // the same in a state's style (hatched when overlapping: a convex polygon is assumed).
    void polygon(const Polygon& polygon, sf::Color color);
    void polygon(const Polygon& polygon, DebugState state);
    // An x of `size` pixels across, centred on `point`.
    void cross(Vec2 point, float size, sf::Color color);

    // An object's world collision box (or bounding circle) in its state's style, and its
    // velocity arrow, which shows where the object will be in a quarter of a second.
    // `colliding`: true draws DebugState::Overlapping, false DebugState::Free.
    void objectBox(const GameObject& object, DebugState state);
    void objectCircle(const GameObject& object, DebugState state);
    void objectBox(const GameObject& object, bool colliding);
    void objectCircle(const GameObject& object, bool colliding);
    // An object as any kind of `shapes` (ShapeTable.h; World::getShapes() for a World's
    // objects): the table's outline in the state's style, and the velocity arrow.
    void objectShape(const GameObject& object, ShapeKind kind, DebugState state,
                     const ShapeTable& shapes = ShapeTable::standard());
    // A contact point and its normal, 24 pixels long.
    void contact(const Contact& contact);

    // Lines of text for the panel in the top-left corner of the window while F1 is on (the
    // window draws them with its font; e.g. explain's answer). Each call adds lines.
    void panel(const std::vector<std::string>& lines);
    [[nodiscard]] const std::vector<std::string>& getPanel() const;

    // Draw everything collected (drawTriangles), then keep it (call clear() to start again).
    // Opaque lines skip blending: the call's render states are renderStatesFor(isOpaque()).
    void draw(sf::RenderTarget& target) const;
    // True while every line collected is fully opaque (alpha 255; also when there are none).
    // Blending an opaque colour writes that colour, so draw() skips it and the same pixels
    // cost the renderer less: a software renderer need not read each pixel back first.
    [[nodiscard]] bool isOpaque() const;
    // Forgets everything collected.
    void clear();
    // Everything collected so far (two triangles a line): tests read it without a window.
    [[nodiscard]] const sf::VertexArray& getVertices() const;

private:
    void dashed(Vec2 from, Vec2 to, sf::Color color);
    // A line as a quad `width` pixels across (two triangles).
    void quad(Vec2 from, Vec2 to, float width, sf::Color color);

    sf::VertexArray vertices{sf::PrimitiveType::Triangles};
    bool opaque = true;      // every vertex so far has alpha 255
    float screenPixel = 1.f; // world units a screen pixel spans (setScreenPixel)
    std::vector<std::string> panelLines;
};

} // namespace hitbox
