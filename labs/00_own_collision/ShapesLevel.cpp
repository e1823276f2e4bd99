#include "ShapesLevel.h"

#include "MyCollision.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <cstdio>

namespace
{
const sf::Color boxColor{70, 110, 190};
const sf::Color circleColor{80, 160, 100};
const sf::Color probeColor{200, 150, 60};
const sf::Color hitColor{210, 70, 60};

// An object centred on its position (its origin point in the middle of the picture).
hitbox::GameObject centred(sf::Vector2f position, sf::Vector2f size)
{
    hitbox::GameObject object;
    object.setSize(size);
    object.setOrigin({size.x / 2.f, size.y / 2.f});
    object.setPosition(position);
    return object;
}

// Turns an object by `degrees` clockwise (SFML 3 takes an sf::Angle, SFML 2 a float).
void turn(hitbox::GameObject& object, float degrees)
{
    hitbox::setRotationDegrees(object, hitbox::getRotationDegrees(object) + degrees);
}

sf::FloatRect rectangleOf(const Sides& sides)
{
    return sf::FloatRect({sides.left, sides.top},
                         {sides.right - sides.left, sides.bottom - sides.top});
}
} // namespace

ShapesLevel::ShapesLevel()
{
    // An upright box, its origin at the top-left corner (the default).
    hitbox::GameObject upright;
    upright.setSize({200.f, 120.f});
    upright.setPosition({90.f, 90.f});
    shapes.push_back({upright, false, false});

    // A box turned by 30 degrees, whose collision box is smaller than its picture.
    hitbox::GameObject turned = centred({560.f, 190.f}, {220.f, 120.f});
    turn(turned, 30.f);
    turned.setCollisionBox(-80.f, -40.f, 160.f, 80.f);
    shapes.push_back({turned, false, false});

    // A box stretched by its scale.
    hitbox::GameObject stretched = centred({960.f, 200.f}, {120.f, 120.f});
    stretched.setScale({1.6f, 0.8f});
    shapes.push_back({stretched, false, false});

    // A ball, and a ball drawn at half its size by its scale.
    shapes.push_back({centred({260.f, 470.f}, {140.f, 140.f}), true, false});
    hitbox::GameObject halfBall = centred({640.f, 500.f}, {200.f, 200.f});
    halfBall.setScale({0.5f, 0.5f});
    shapes.push_back({halfBall, true, false});

    // A wide box whose circle is set by its shorter side.
    shapes.push_back({centred({960.f, 500.f}, {240.f, 80.f}), true, false});

    probe = {centred({455.f, 245.f}, {80.f, 80.f}), true, false};
    update(0.f); // the first frame already shows what the probe hits
}

void ShapesLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.getMousePosition() != lastMouseReading)
        probe.object.setPosition(input.getMousePosition());
    lastMouseReading = input.getMousePosition();
    if (input.isPressed(sf::Keyboard::Key::Space))
        probe.isCircle = !probe.isCircle;
}

bool ShapesLevel::collide(Shape& first, Shape& second)
{
    if (first.isCircle && second.isCircle)
        return MyCollision::checkBoundingCircle(&first.object, &second.object);
    if (first.isCircle)
        return MyCollision::checkCircleBox(&first.object, &second.object);
    if (second.isCircle)
        return MyCollision::checkCircleBox(&second.object, &first.object);
    return MyCollision::checkBoundingBox(&first.object, &second.object);
}

void ShapesLevel::update(float)
{
    probe.hit = false;
    for (Shape& shape : shapes)
    {
        shape.hit = collide(probe, shape);
        probe.hit = probe.hit || shape.hit;
    }
}

void ShapesLevel::render(sf::RenderTarget& target) const
{
    auto draw = [&target](const Shape& shape, sf::Color color)
    {
        const sf::Color fill = shape.hit ? hitColor : color;
        if (!shape.isCircle)
        {
            sf::RectangleShape picture = shape.object;
            picture.setFillColor(fill);
            target.draw(picture);
            return;
        }
        // A ball is drawn as the circle your worldCircle returns.
        const WorldCircle circle = MyCollision::worldCircle(shape.object);
        sf::CircleShape picture(circle.radius);
        picture.setOrigin({circle.radius, circle.radius});
        picture.setPosition(circle.center);
        picture.setFillColor(fill);
        target.draw(picture);
    };
    for (const Shape& shape : shapes)
        draw(shape, shape.isCircle ? circleColor : boxColor);
    draw(probe, probeColor);
}

void ShapesLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    auto outline = [&debug](const Shape& shape)
    {
        // Colour and line style: hatched when it collides, a plain outline when free.
        const hitbox::DebugState state =
            shape.hit ? hitbox::DebugState::Overlapping : hitbox::DebugState::Free;
        if (shape.isCircle)
        {
            const WorldCircle circle = MyCollision::worldCircle(shape.object);
            debug.circle(hitbox::Circle{hitbox::toVec2(circle.center), circle.radius}, state);
        }
        else
        {
            debug.box(hitbox::toBox(rectangleOf(MyCollision::worldBox(shape.object))), state);
        }
    };
    for (const Shape& shape : shapes)
        outline(shape);
    outline(probe);
}

std::string ShapesLevel::getHelpText() const
{
    return "Mouse moves the probe   Space ball or box";
}

std::string ShapesLevel::describeState() const
{
    char text[80];
    std::snprintf(text, sizeof text, "probe is a %s, hitting %d object(s)",
                  probe.isCircle ? "ball" : "box", getHitCount());
    return text;
}

int ShapesLevel::getHitCount() const
{
    int count = 0;
    for (const Shape& shape : shapes)
        count += shape.hit ? 1 : 0;
    return count;
}
