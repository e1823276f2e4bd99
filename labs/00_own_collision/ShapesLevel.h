// ShapesLevel.h - shapes that light up when your own collision tests say they are hit.
//
// A probe (a ball, or a box: Space switches) follows the mouse. Every other object is
// tested against it with MyCollision, the class you write, and turns red while it is hit.
// The objects have moved origins, scales, rotations and collision boxes smaller than their
// pictures, so each rule of the lab shows on screen. F1 draws the boxes and circles your
// worldBox and worldCircle return.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/objects/GameObject.h"

#include <string>
#include <vector>

class ShapesLevel : public hitbox::Level
{
public:
    ShapesLevel();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // How many objects the probe hits, by MyCollision's answers (for tests and the state line).
    int getHitCount() const;

private:
    struct Shape
    {
        hitbox::GameObject object;
        bool isCircle = false;
        bool hit = false;
    };
    // The one MyCollision test that fits the two shapes.
    static bool collide(Shape& first, Shape& second);

    std::vector<Shape> shapes;
    Shape probe;
    // Where the mouse was when it last moved: the probe starts over an object so that a
    // --screenshot shows a hit; it follows the real mouse once that moves.
    sf::Vector2f lastMouseReading;
};
