#include "ConformancePack.h"

#include "MyCollision.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/objects/Collision.h"
#include "hitbox/objects/GameObject.h"
#include "hitbox/sfml/Conversions.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/Rect.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

namespace
{
using conformance::Variant;

const float notANumber = std::numeric_limits<float>::quiet_NaN();
// Random cases per check: enough to meet every rule many times, fast in a debug build.
constexpr int randomCases = 2000;

// SFML 2 and SFML 3 spell rotations and rectangles differently: the framework's helpers
// (hitbox/sfml/) read both.
void turn(hitbox::GameObject& object, float degrees)
{
    hitbox::setRotationDegrees(object, degrees);
}
float degreesOf(const hitbox::GameObject& object)
{
    return hitbox::getRotationDegrees(object);
}
Sides sidesOf(const sf::FloatRect& rect)
{
    const hitbox::Box box = hitbox::toBox(rect);
    return {box.left, box.top, box.left + box.width, box.top + box.height};
}

std::string text(sf::Vector2f vector)
{
    std::ostringstream out;
    out << "(" << vector.x << ", " << vector.y << ")";
    return out.str();
}

std::string text(const Sides& sides)
{
    std::ostringstream out;
    out << "{left " << sides.left << ", top " << sides.top << ", right " << sides.right
        << ", bottom " << sides.bottom << "}";
    return out.str();
}

// An object as a student set it up: only what differs from a plain box is printed.
std::string describe(const hitbox::GameObject* object)
{
    if (object == nullptr)
        return "nullptr";
    std::ostringstream out;
    out << "{position " << text(object->getPosition()) << ", size " << object->getSize().x << " x "
        << object->getSize().y;
    if (object->getOrigin() != sf::Vector2f())
        out << ", origin " << text(object->getOrigin());
    if (object->getScale() != sf::Vector2f(1.f, 1.f))
        out << ", scale " << text(object->getScale());
    if (degreesOf(*object) != 0.f)
        out << ", rotated " << degreesOf(*object) << " degrees";
    const Sides local = sidesOf(object->getLocalCollisionBox());
    const sf::Vector2f origin = object->getOrigin();
    if (local.left != -origin.x || local.top != -origin.y ||
        local.right != object->getSize().x - origin.x ||
        local.bottom != object->getSize().y - origin.y)
        out << ", setCollisionBox(" << local.left << ", " << local.top << ", "
            << local.right - local.left << ", " << local.bottom - local.top << ")";
    if (!object->isAlive())
        out << ", dead";
    out << "}";
    return out.str();
}

// A variant's point and length.
sf::Vector2f at(const Variant& variant, float x, float y)
{
    return variant.offset + sf::Vector2f(x, y) * variant.unit;
}

// A plain box (origin at its top-left corner, no scale, no rotation): the tests of tasks
// 2, 3 and 5 use only these, so a mistake in task 1's worldBox costs task 1 alone.
hitbox::GameObject box(const Variant& variant, float left, float top, float width, float height)
{
    hitbox::GameObject object;
    object.setPosition(at(variant, left, top));
    object.setSize(sf::Vector2f(width, height) * variant.unit);
    return object;
}

// A plain ball: a square whose inscribed circle has this centre and radius.
hitbox::GameObject ball(const Variant& variant, float centerX, float centerY, float radius)
{
    return box(variant, centerX - radius, centerY - radius, 2.f * radius, 2.f * radius);
}

bool near(float actual, float expected)
{
    if (std::isnan(expected))
        return std::isnan(actual);
    return std::abs(actual - expected) <= 1e-3f * (1.f + std::abs(expected));
}

bool near(const Sides& actual, const Sides& expected)
{
    return near(actual.left, expected.left) && near(actual.top, expected.top) &&
           near(actual.right, expected.right) && near(actual.bottom, expected.bottom);
}

void expectWorldBox(const char* rule, const hitbox::GameObject& object, const Sides& expected)
{
    const Sides actual = MyCollision::worldBox(object);
    EXPECT_TRUE(near(actual, expected))
        << "worldBox of " << rule << " is " << text(actual) << ", expected " << text(expected)
        << ": object = " << describe(&object);
}

// Tasks 2, 3 and 5 call task 1's worldBox (task 5 also task 4's worldCircle). They are
// judged on the shapes YOUR functions give, so a mistake in worldBox or worldCircle costs
// its own task alone: where your shapes are the framework's, the case's stated answer
// stands; where they differ, the framework's edge rule (hitbox/geometry/Shapes.h and
// Overlap.h) applied to your shapes decides.
struct Judged
{
    bool expected = false;
    std::string note; // empty when your shapes are the framework's
};

bool same(float a, float b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}

bool same(const Sides& a, const Sides& b)
{
    return same(a.left, b.left) && same(a.top, b.top) && same(a.right, b.right) &&
           same(a.bottom, b.bottom);
}

bool same(const WorldCircle& a, const hitbox::Circle& b)
{
    return same(a.center.x, b.center.x) && same(a.center.y, b.center.y) && same(a.radius, b.radius);
}

// The framework's world collision box: the answer to task 1.
Sides referenceBox(const hitbox::GameObject& object)
{
    return sidesOf(object.getCollisionBox());
}

std::string yourShapesNote(const std::string& shapes)
{
    return " (judged on the shapes your task 1 and 4 functions give, which differ from the "
           "framework's: " +
           shapes + ")";
}

Judged judgeBoxes(bool stated, hitbox::GameObject& first, hitbox::GameObject& second)
{
    if (!MyCollision::canCollide(&first, &second))
        return {stated, ""};
    const Sides a = MyCollision::worldBox(first);
    const Sides b = MyCollision::worldBox(second);
    if (same(a, referenceBox(first)) && same(b, referenceBox(second)))
        return {stated, ""};
    return {hitbox::spansOverlap(a.left, a.right, b.left, b.right) &&
                hitbox::spansOverlap(a.top, a.bottom, b.top, b.bottom),
            yourShapesNote("worldBox A = " + text(a) + ", B = " + text(b))};
}

Judged judgePoint(bool stated, hitbox::GameObject& object, sf::Vector2f point)
{
    if (!MyCollision::canCollide(&object))
        return {stated, ""};
    const Sides box = MyCollision::worldBox(object);
    if (same(box, referenceBox(object)))
        return {stated, ""};
    return {hitbox::spansOverlap(point.x, point.x, box.left, box.right) &&
                hitbox::spansOverlap(point.y, point.y, box.top, box.bottom),
            yourShapesNote("worldBox = " + text(box))};
}

Judged judgeCircleBox(bool stated, hitbox::GameObject& circleObject, hitbox::GameObject& boxObject)
{
    if (!MyCollision::canCollide(&circleObject, &boxObject))
        return {stated, ""};
    const WorldCircle circle = MyCollision::worldCircle(circleObject);
    const Sides box = MyCollision::worldBox(boxObject);
    if (same(circle, circleObject.getBoundingCircle()) && same(box, referenceBox(boxObject)))
        return {stated, ""};
    // Sides the wrong way round (left > right) are no box, as NaN sides are: no collision.
    const bool isABox = box.left <= box.right && box.top <= box.bottom;
    const hitbox::Box plain{box.left, box.top, box.right - box.left, box.bottom - box.top};
    return {isABox && hitbox::circleVsBox({hitbox::toVec2(circle.center), circle.radius}, plain),
            yourShapesNote("worldCircle centre " + text(circle.center) + " radius " +
                           std::to_string(circle.radius) + ", worldBox = " + text(box))};
}

// `rule` names the case, e.g. "boxes touching on the left edge". Both argument orders.
void expectBoxes(bool collide, const std::string& rule, hitbox::GameObject first,
                 hitbox::GameObject second)
{
    const Judged judged = judgeBoxes(collide, first, second);
    const bool answer = MyCollision::checkBoundingBox(&first, &second);
    EXPECT_EQ(answer, judged.expected)
        << rule << " were reported as " << (answer ? "colliding" : "not colliding")
        << ": A = " << describe(&first) << ", B = " << describe(&second) << judged.note;
    const bool swapped = MyCollision::checkBoundingBox(&second, &first);
    EXPECT_EQ(swapped, judged.expected)
        << rule << " with the arguments swapped were reported as "
        << (swapped ? "colliding" : "not colliding") << ": A = " << describe(&second)
        << ", B = " << describe(&first) << judged.note;
}

void expectPoint(bool inside, const std::string& rule, hitbox::GameObject object,
                 sf::Vector2f point)
{
    const Judged judged = judgePoint(inside, object, point);
    const bool answer = MyCollision::checkBoundingBox(&object, point);
    EXPECT_EQ(answer, judged.expected)
        << rule << " was reported as " << (answer ? "inside" : "outside")
        << ": point = " << text(point) << ", box = " << describe(&object) << judged.note;
}

void expectCircles(bool collide, const std::string& rule, hitbox::GameObject first,
                   hitbox::GameObject second)
{
    const bool answer = MyCollision::checkBoundingCircle(&first, &second);
    EXPECT_EQ(answer, collide) << rule << " were reported as "
                               << (answer ? "colliding" : "not colliding")
                               << ": A = " << describe(&first) << ", B = " << describe(&second);
    const bool swapped = MyCollision::checkBoundingCircle(&second, &first);
    EXPECT_EQ(swapped, collide) << rule << " with the arguments swapped were reported as "
                                << (swapped ? "colliding" : "not colliding")
                                << ": A = " << describe(&second) << ", B = " << describe(&first);
}

void expectCircleBox(bool collide, const std::string& rule, hitbox::GameObject circle,
                     hitbox::GameObject boxObject)
{
    const Judged judged = judgeCircleBox(collide, circle, boxObject);
    const bool answer = MyCollision::checkCircleBox(&circle, &boxObject);
    EXPECT_EQ(answer, judged.expected)
        << rule << " was reported as " << (answer ? "colliding" : "not colliding")
        << ": circle object = " << describe(&circle) << ", box object = " << describe(&boxObject)
        << judged.note;
}

// Whole numbers between low and high: on a coarse grid, touching happens often.
float wholeBetween(std::mt19937& random, int low, int high)
{
    return static_cast<float>(std::uniform_int_distribution<int>(low, high)(random));
}

hitbox::GameObject randomPlainBox(const Variant& variant, std::mt19937& random)
{
    return box(variant, wholeBetween(random, 0, 20), wholeBetween(random, 0, 20),
               wholeBetween(random, 0, 10), wholeBetween(random, 0, 10));
}

// The same sides in any order of the four corners.
const char* const sideNames[] = {"left", "right", "top", "bottom"};
} // namespace

namespace conformance
{

void checkWorldBox(const Variant& variant)
{
    const float u = variant.unit;
    const sf::Vector2f p = at(variant, 100.f, 100.f);

    hitbox::GameObject plain = box(variant, 100.f, 100.f, 40.f, 20.f);
    expectWorldBox("a plain box", plain, {p.x, p.y, p.x + 40.f * u, p.y + 20.f * u});

    hitbox::GameObject smaller = box(variant, 100.f, 100.f, 40.f, 20.f);
    smaller.setCollisionBox(5.f * u, 2.f * u, 10.f * u, 8.f * u);
    expectWorldBox("a collision box smaller than the picture", smaller,
                   {p.x + 5.f * u, p.y + 2.f * u, p.x + 15.f * u, p.y + 10.f * u});

    hitbox::GameObject centred = box(variant, 100.f, 100.f, 40.f, 20.f);
    centred.setOrigin(sf::Vector2f(20.f, 10.f) * u);
    expectWorldBox("a box whose origin is its centre", centred,
                   {p.x - 20.f * u, p.y - 10.f * u, p.x + 20.f * u, p.y + 10.f * u});

    hitbox::GameObject centredSmaller = centred;
    centredSmaller.setCollisionBox(-4.f * u, -6.f * u, 8.f * u, 12.f * u);
    expectWorldBox("a collision box measured from a moved origin", centredSmaller,
                   {p.x - 4.f * u, p.y - 6.f * u, p.x + 4.f * u, p.y + 6.f * u});

    hitbox::GameObject scaled = box(variant, 100.f, 100.f, 40.f, 20.f);
    scaled.setScale({2.f, 3.f});
    expectWorldBox("a scaled box", scaled, {p.x, p.y, p.x + 80.f * u, p.y + 60.f * u});

    hitbox::GameObject scaledCentred = centred;
    scaledCentred.setScale({2.f, 3.f});
    expectWorldBox("a box scaled about its centre", scaledCentred,
                   {p.x - 40.f * u, p.y - 30.f * u, p.x + 40.f * u, p.y + 30.f * u});

    hitbox::GameObject mirrored = box(variant, 100.f, 100.f, 40.f, 20.f);
    mirrored.setScale({-1.f, 1.f});
    expectWorldBox("a box mirrored by a negative scale", mirrored,
                   {p.x - 40.f * u, p.y, p.x, p.y + 20.f * u});

    hitbox::GameObject quarterTurn = centred;
    turn(quarterTurn, 90.f);
    expectWorldBox("a box turned by 90 degrees about its centre", quarterTurn,
                   {p.x - 10.f * u, p.y - 20.f * u, p.x + 10.f * u, p.y + 20.f * u});

    hitbox::GameObject eighthTurn = box(variant, 100.f, 100.f, 20.f, 20.f);
    eighthTurn.setOrigin(sf::Vector2f(10.f, 10.f) * u);
    turn(eighthTurn, 45.f);
    const float halfDiagonal = 10.f * u * std::sqrt(2.f);
    expectWorldBox(
        "a square turned by 45 degrees (the box around it)", eighthTurn,
        {p.x - halfDiagonal, p.y - halfDiagonal, p.x + halfDiagonal, p.y + halfDiagonal});

    hitbox::GameObject backwards = box(variant, 100.f, 100.f, 40.f, 20.f);
    backwards.setCollisionBox(10.f * u, 0.f, -20.f * u, 10.f * u);
    expectWorldBox("a collision box with a negative width (it spans backwards)", backwards,
                   {p.x - 10.f * u, p.y, p.x + 10.f * u, p.y + 10.f * u});

    hitbox::GameObject point = box(variant, 100.f, 100.f, 0.f, 0.f);
    expectWorldBox("a box of size zero", point, {p.x, p.y, p.x, p.y});

    hitbox::GameObject lost = box(variant, 100.f, 100.f, 40.f, 20.f);
    lost.setPosition({notANumber, notANumber});
    expectWorldBox("a box at a NaN position", lost,
                   {notANumber, notANumber, notANumber, notANumber});

    // Random objects: every combination of origin, scale, rotation and collision box.
    std::mt19937 random(variant.seed);
    for (int index = 0; index < randomCases; ++index)
    {
        hitbox::GameObject object =
            box(variant, wholeBetween(random, -50, 50), wholeBetween(random, -50, 50),
                wholeBetween(random, 0, 40), wholeBetween(random, 0, 40));
        object.setOrigin(
            sf::Vector2f(wholeBetween(random, -20, 20), wholeBetween(random, -20, 20)) * u);
        object.setScale({wholeBetween(random, -8, 8) / 4.f, wholeBetween(random, -8, 8) / 4.f});
        turn(object, wholeBetween(random, 0, 23) * 15.f);
        if (random() % 2 == 0)
            object.setCollisionBox(
                wholeBetween(random, -20, 20) * u, wholeBetween(random, -20, 20) * u,
                wholeBetween(random, -20, 20) * u, wholeBetween(random, -20, 20) * u);
        const Sides expected = sidesOf(object.getCollisionBox());
        const Sides actual = MyCollision::worldBox(object);
        if (!near(actual, expected))
        {
            ADD_FAILURE() << "random case " << index << " (seed " << variant.seed
                          << "): worldBox is " << text(actual)
                          << ", the framework's collision box is " << text(expected)
                          << ": object = " << describe(&object);
            return; // one random failure says enough
        }
    }
}

void checkBoxAgainstBox(const Variant& variant)
{
    // B is 20 x 20 at (100, 100); A is 10 x 10 around it.
    const hitbox::GameObject b = box(variant, 100.f, 100.f, 20.f, 20.f);
    expectBoxes(true, "overlapping boxes", box(variant, 95.f, 95.f, 10.f, 10.f), b);
    const float touching[4][2] = {{90.f, 105.f}, {120.f, 105.f}, {105.f, 90.f}, {105.f, 120.f}};
    const float hair[4][2] = {{90.5f, 105.f}, {119.5f, 105.f}, {105.f, 90.5f}, {105.f, 119.5f}};
    for (int side = 0; side < 4; ++side)
    {
        const std::string where = sideNames[side];
        expectBoxes(false, "boxes touching on the " + where + " edge",
                    box(variant, touching[side][0], touching[side][1], 10.f, 10.f), b);
        expectBoxes(true, "boxes overlapping by half a pixel on the " + where + " edge",
                    box(variant, hair[side][0], hair[side][1], 10.f, 10.f), b);
    }
    const float corners[4][2] = {{90.f, 90.f}, {120.f, 90.f}, {90.f, 120.f}, {120.f, 120.f}};
    const char* const cornerNames[] = {"top-left", "top-right", "bottom-left", "bottom-right"};
    for (int corner = 0; corner < 4; ++corner)
        expectBoxes(false, std::string("boxes touching at the ") + cornerNames[corner] + " corner",
                    box(variant, corners[corner][0], corners[corner][1], 10.f, 10.f), b);
    expectBoxes(false, "boxes apart on x but level on y", box(variant, 130.f, 105.f, 10.f, 10.f),
                b);
    expectBoxes(false, "boxes apart on y but level on x", box(variant, 105.f, 130.f, 10.f, 10.f),
                b);
    expectBoxes(true, "crossing boxes (no corner inside the other)",
                box(variant, 105.f, 80.f, 10.f, 60.f), box(variant, 80.f, 105.f, 60.f, 10.f));
    expectBoxes(true, "a box inside a bigger box", box(variant, 105.f, 105.f, 5.f, 5.f), b);
    expectBoxes(true, "equal boxes in the same place", box(variant, 100.f, 100.f, 20.f, 20.f), b);
    expectBoxes(true, "a zero-size box strictly inside a box", box(variant, 110.f, 110.f, 0.f, 0.f),
                b);
    expectBoxes(false, "a zero-size box on an edge", box(variant, 100.f, 110.f, 0.f, 0.f), b);
    expectBoxes(true, "a box of zero width crossing a box", box(variant, 110.f, 90.f, 0.f, 40.f),
                b);
    hitbox::GameObject lost = box(variant, 105.f, 105.f, 10.f, 10.f);
    lost.setPosition({notANumber, notANumber});
    expectBoxes(false, "a box at a NaN position and a box", lost, b);
    hitbox::GameObject lostX = box(variant, 105.f, 105.f, 10.f, 10.f);
    lostX.setPosition({notANumber, 105.f * variant.unit + variant.offset.y});
    expectBoxes(false, "a box whose x is NaN and a box", lostX, b);

    hitbox::GameObject alone = box(variant, 100.f, 100.f, 20.f, 20.f);
    EXPECT_FALSE(MyCollision::checkBoundingBox(&alone, &alone))
        << "an object tested against itself was reported as colliding: A = B = "
        << describe(&alone);
    EXPECT_FALSE(MyCollision::checkBoundingBox(&alone, nullptr))
        << "a box and a nullptr were reported as colliding: A = " << describe(&alone);
    hitbox::GameObject dead = box(variant, 105.f, 105.f, 10.f, 10.f);
    dead.setAlive(false);
    expectBoxes(false, "a dead box and a box", dead, b);

    std::mt19937 random(variant.seed);
    for (int index = 0; index < randomCases; ++index)
    {
        hitbox::GameObject first = randomPlainBox(variant, random);
        hitbox::GameObject second = randomPlainBox(variant, random);
        const Judged judged =
            judgeBoxes(hitbox::Collision::checkBoundingBox(&first, &second), first, second);
        const bool expected = judged.expected;
        if (MyCollision::checkBoundingBox(&first, &second) != expected)
        {
            ADD_FAILURE() << "random case " << index << " (seed " << variant.seed << "): boxes "
                          << (expected ? "that overlap" : "that do not overlap")
                          << " were reported as " << (expected ? "not colliding" : "colliding")
                          << ": A = " << describe(&first) << ", B = " << describe(&second)
                          << judged.note;
            return;
        }
    }
}

void checkPointInBox(const Variant& variant)
{
    const hitbox::GameObject b = box(variant, 100.f, 100.f, 20.f, 20.f);
    expectPoint(true, "a point inside the box", b, at(variant, 110.f, 105.f));
    const float onEdge[4][2] = {{100.f, 110.f}, {120.f, 110.f}, {110.f, 100.f}, {110.f, 120.f}};
    const float justIn[4][2] = {{100.5f, 110.f}, {119.5f, 110.f}, {110.f, 100.5f}, {110.f, 119.5f}};
    for (int side = 0; side < 4; ++side)
    {
        const std::string where = sideNames[side];
        expectPoint(false, "a point on the " + where + " edge", b,
                    at(variant, onEdge[side][0], onEdge[side][1]));
        expectPoint(true, "a point half a pixel inside the " + where + " edge", b,
                    at(variant, justIn[side][0], justIn[side][1]));
    }
    expectPoint(false, "a point on the top-left corner", b, at(variant, 100.f, 100.f));
    expectPoint(false, "a point on the bottom-right corner", b, at(variant, 120.f, 120.f));
    expectPoint(false, "a point beside the box (level with it on y)", b, at(variant, 130.f, 110.f));
    expectPoint(false, "a point below the box (level with it on x)", b, at(variant, 110.f, 130.f));
    expectPoint(false, "a NaN point", b, {notANumber, notANumber});
    expectPoint(false, "a point in the place of a zero-size box",
                box(variant, 100.f, 100.f, 0.f, 0.f), at(variant, 100.f, 100.f));
    hitbox::GameObject dead = b;
    dead.setAlive(false);
    expectPoint(false, "a point inside a dead box", dead, at(variant, 110.f, 110.f));

    std::mt19937 random(variant.seed);
    for (int index = 0; index < randomCases; ++index)
    {
        hitbox::GameObject object = randomPlainBox(variant, random);
        const sf::Vector2f point =
            at(variant, wholeBetween(random, 0, 30), wholeBetween(random, 0, 30));
        const Judged judged =
            judgePoint(hitbox::Collision::checkBoundingBox(&object, point), object, point);
        const bool expected = judged.expected;
        if (MyCollision::checkBoundingBox(&object, point) != expected)
        {
            ADD_FAILURE() << "random case " << index << " (seed " << variant.seed << "): a point "
                          << (expected ? "inside" : "outside") << " was reported "
                          << (expected ? "outside" : "inside") << ": point = " << text(point)
                          << ", box = " << describe(&object) << judged.note;
            return;
        }
    }
}

void checkBoundingCircle(const Variant& variant)
{
    const float u = variant.unit;
    const sf::Vector2f p = at(variant, 100.f, 100.f);
    auto expectCircle =
        [](const char* rule, const hitbox::GameObject& object, sf::Vector2f center, float radius)
    {
        const WorldCircle circle = MyCollision::worldCircle(object);
        EXPECT_TRUE(near(circle.center.x, center.x) && near(circle.center.y, center.y) &&
                    near(circle.radius, radius))
            << "worldCircle of " << rule << " has centre " << text(circle.center) << " and radius "
            << circle.radius << ", expected " << text(center) << " and " << radius
            << ": object = " << describe(&object);
    };
    expectCircle("a plain square", box(variant, 100.f, 100.f, 40.f, 40.f),
                 p + sf::Vector2f(20.f, 20.f) * u, 20.f * u);
    expectCircle("a box wider than it is tall (half the shorter side)",
                 box(variant, 100.f, 100.f, 80.f, 40.f), p + sf::Vector2f(40.f, 20.f) * u,
                 20.f * u);
    expectCircle("a box taller than it is wide (half the shorter side)",
                 box(variant, 100.f, 100.f, 40.f, 80.f), p + sf::Vector2f(20.f, 40.f) * u,
                 20.f * u);
    hitbox::GameObject smaller = box(variant, 100.f, 100.f, 40.f, 40.f);
    smaller.setCollisionBox(10.f * u, 10.f * u, 10.f * u, 10.f * u);
    expectCircle("a collision box smaller than the picture", smaller,
                 p + sf::Vector2f(15.f, 15.f) * u, 5.f * u);
    hitbox::GameObject centred = box(variant, 100.f, 100.f, 40.f, 40.f);
    centred.setOrigin(sf::Vector2f(20.f, 20.f) * u);
    expectCircle("a square whose origin is its centre", centred, p, 20.f * u);
    hitbox::GameObject doubled = centred;
    doubled.setScale({2.f, 2.f});
    expectCircle("a square scaled by 2", doubled, p, 40.f * u);
    hitbox::GameObject stretched = centred;
    stretched.setScale({3.f, 1.f});
    expectCircle("a square stretched 3 times on x (the shorter side after scaling)", stretched, p,
                 20.f * u);
    hitbox::GameObject mirrored = box(variant, 100.f, 100.f, 40.f, 40.f);
    mirrored.setScale({-1.f, 1.f});
    expectCircle("a square mirrored by a negative scale", mirrored,
                 p + sf::Vector2f(-20.f, 20.f) * u, 20.f * u);
    hitbox::GameObject flipped = box(variant, 100.f, 100.f, 40.f, 40.f);
    flipped.setScale({1.f, -1.f});
    expectCircle("a square flipped upside down by a negative scale", flipped,
                 p + sf::Vector2f(20.f, -20.f) * u, 20.f * u);
    hitbox::GameObject turned = box(variant, 100.f, 100.f, 80.f, 40.f);
    turned.setOrigin(sf::Vector2f(20.f, 20.f) * u);
    turn(turned, 90.f);
    expectCircle("a box turned by 90 degrees about a point that is not its centre", turned,
                 p + sf::Vector2f(0.f, 20.f) * u, 20.f * u);

    // Pairs: ball(x, y, r) is a plain square around that circle.
    const hitbox::GameObject b = ball(variant, 100.f, 100.f, 20.f);
    expectCircles(true, "overlapping circles", ball(variant, 120.f, 100.f, 10.f), b);
    expectCircles(false, "circles touching along x", ball(variant, 130.f, 100.f, 10.f), b);
    expectCircles(false, "circles touching along y", ball(variant, 100.f, 70.f, 10.f), b);
    expectCircles(true, "circles overlapping by half a pixel along x",
                  ball(variant, 129.5f, 100.f, 10.f), b);
    // 3-4-5: centres 25 apart on a diagonal, radii 20 and 5.
    expectCircles(false, "circles touching on a diagonal", ball(variant, 115.f, 120.f, 5.f), b);
    expectCircles(true, "circles overlapping on a diagonal", ball(variant, 114.f, 119.f, 5.f), b);
    expectCircles(false, "circles apart on a diagonal whose boxes overlap",
                  ball(variant, 118.f, 118.f, 5.f), b);
    expectCircles(true, "a circle inside a bigger circle", ball(variant, 105.f, 100.f, 5.f), b);
    expectCircles(true, "equal circles on the same centre", ball(variant, 100.f, 100.f, 20.f), b);
    hitbox::GameObject lost = ball(variant, 110.f, 100.f, 10.f);
    lost.setPosition({notANumber, notANumber});
    expectCircles(false, "a circle at a NaN position and a circle", lost, b);
    hitbox::GameObject scaledBall = ball(variant, 100.f, 100.f, 10.f);
    scaledBall.setOrigin(sf::Vector2f(10.f, 10.f) * u);
    scaledBall.setPosition(at(variant, 145.f, 100.f));
    scaledBall.setScale({2.f, 2.f});
    expectCircles(false, "a circle scaled to radius 20 that touches another", scaledBall,
                  ball(variant, 100.f, 100.f, 25.f));
    // Objects that cannot collide (canCollide), even where their circles overlap.
    hitbox::GameObject alone = ball(variant, 100.f, 100.f, 20.f);
    EXPECT_FALSE(MyCollision::checkBoundingCircle(&alone, &alone))
        << "an object tested against itself was reported as colliding: A = B = "
        << describe(&alone);
    EXPECT_FALSE(MyCollision::checkBoundingCircle(&alone, nullptr))
        << "a circle and a nullptr were reported as colliding: A = " << describe(&alone);
    hitbox::GameObject dead = ball(variant, 110.f, 100.f, 10.f);
    dead.setAlive(false);
    expectCircles(false, "a dead circle and a circle it overlaps", dead, b);

    std::mt19937 random(variant.seed);
    for (int index = 0; index < randomCases; ++index)
    {
        hitbox::GameObject objects[2];
        for (hitbox::GameObject& object : objects)
        {
            object = box(variant, wholeBetween(random, 0, 40), wholeBetween(random, 0, 40),
                         wholeBetween(random, 0, 20), wholeBetween(random, 0, 20));
            object.setOrigin(
                sf::Vector2f(wholeBetween(random, 0, 10), wholeBetween(random, 0, 10)) * u);
            object.setScale({wholeBetween(random, 1, 4) / 2.f, wholeBetween(random, 1, 4) / 2.f});
            if (random() % 2 == 0)
                object.setCollisionBox(
                    wholeBetween(random, -5, 5) * u, wholeBetween(random, -5, 5) * u,
                    wholeBetween(random, 0, 10) * u, wholeBetween(random, 0, 10) * u);
        }
        const bool expected = hitbox::Collision::checkBoundingCircle(&objects[0], &objects[1]);
        if (MyCollision::checkBoundingCircle(&objects[0], &objects[1]) != expected)
        {
            ADD_FAILURE() << "random case " << index << " (seed " << variant.seed << "): circles "
                          << (expected ? "that overlap" : "that do not overlap")
                          << " were reported as " << (expected ? "not colliding" : "colliding")
                          << ": A = " << describe(&objects[0]) << ", B = " << describe(&objects[1]);
            return;
        }
    }
}

void checkCircleAgainstBox(const Variant& variant)
{
    // The box is 20 x 20 at (100, 100); circles of radius 5 around it.
    const hitbox::GameObject b = box(variant, 100.f, 100.f, 20.f, 20.f);
    expectCircleBox(true, "a circle overlapping a box", ball(variant, 98.f, 110.f, 5.f), b);
    const float touching[4][2] = {{95.f, 110.f}, {125.f, 110.f}, {110.f, 95.f}, {110.f, 125.f}};
    const float hair[4][2] = {{95.5f, 110.f}, {124.5f, 110.f}, {110.f, 95.5f}, {110.f, 124.5f}};
    for (int side = 0; side < 4; ++side)
    {
        const std::string where = sideNames[side];
        expectCircleBox(false, "a circle touching the " + where + " edge of a box",
                        ball(variant, touching[side][0], touching[side][1], 5.f), b);
        expectCircleBox(true, "a circle reaching half a pixel past the " + where + " edge of a box",
                        ball(variant, hair[side][0], hair[side][1], 5.f), b);
    }
    // 3-4-5 from the corner (120, 120): the circle's square overlaps the box, the circle not.
    expectCircleBox(false, "a circle touching the bottom-right corner of a box",
                    ball(variant, 123.f, 124.f, 5.f), b);
    expectCircleBox(true, "a circle reaching past the bottom-right corner of a box",
                    ball(variant, 122.f, 123.f, 5.f), b);
    expectCircleBox(false, "a circle off the top-left corner whose square overlaps the box",
                    ball(variant, 96.f, 96.f, 5.f), b);
    expectCircleBox(true, "a circle whose centre is inside the box",
                    ball(variant, 110.f, 110.f, 5.f), b);
    expectCircleBox(true, "a circle bigger than the box around it",
                    ball(variant, 110.f, 110.f, 50.f), b);
    expectCircleBox(true, "a zero-size circle (a point) strictly inside a box",
                    ball(variant, 110.f, 110.f, 0.f), b);
    expectCircleBox(false, "a zero-size circle (a point) on the edge of a box",
                    ball(variant, 100.f, 110.f, 0.f), b);
    // Argument order: the small circle sits in the corner of a big box. The big box's own
    // circle does not reach the corner, so swapping the two objects gives the wrong answer.
    expectCircleBox(true,
                    "a small circle in the corner of a big box (the circle is the first argument)",
                    ball(variant, 6.f, 6.f, 5.f), box(variant, 0.f, 0.f, 100.f, 100.f));
    hitbox::GameObject lostCircle = ball(variant, 110.f, 110.f, 5.f);
    lostCircle.setPosition({notANumber, notANumber});
    expectCircleBox(false, "a circle at a NaN position", lostCircle, b);
    hitbox::GameObject lostBox = b;
    lostBox.setPosition({notANumber, notANumber});
    expectCircleBox(false, "a circle against a box at a NaN position",
                    ball(variant, 110.f, 110.f, 5.f), lostBox);
    // Only x is NaN: the circle is level with the box on y, which alone must not be enough.
    hitbox::GameObject lostBoxX = b;
    lostBoxX.setPosition({notANumber, 100.f * variant.unit + variant.offset.y});
    expectCircleBox(false, "a circle against a box whose x is NaN (level with it on y)",
                    ball(variant, 110.f, 110.f, 5.f), lostBoxX);
    hitbox::GameObject lostBoxY = b;
    lostBoxY.setPosition({100.f * variant.unit + variant.offset.x, notANumber});
    expectCircleBox(false, "a circle against a box whose y is NaN (level with it on x)",
                    ball(variant, 110.f, 110.f, 5.f), lostBoxY);
    // Objects that cannot collide (canCollide), even where the circle reaches into the box.
    hitbox::GameObject alone = ball(variant, 110.f, 110.f, 5.f);
    EXPECT_FALSE(MyCollision::checkCircleBox(&alone, &alone))
        << "an object tested against itself was reported as colliding: " << describe(&alone);
    EXPECT_FALSE(MyCollision::checkCircleBox(&alone, nullptr))
        << "a circle and a nullptr were reported as colliding: " << describe(&alone);
    EXPECT_FALSE(MyCollision::checkCircleBox(nullptr, &alone))
        << "a nullptr and a box were reported as colliding: " << describe(&alone);
    hitbox::GameObject deadCircle = ball(variant, 110.f, 110.f, 5.f);
    deadCircle.setAlive(false);
    expectCircleBox(false, "a dead circle inside a box", deadCircle, b);

    std::mt19937 random(variant.seed);
    for (int index = 0; index < randomCases; ++index)
    {
        hitbox::GameObject circle = ball(variant, wholeBetween(random, 0, 30),
                                         wholeBetween(random, 0, 30), wholeBetween(random, 0, 8));
        hitbox::GameObject boxObject = randomPlainBox(variant, random);
        const Judged judged = judgeCircleBox(hitbox::Collision::checkCircleBox(&circle, &boxObject),
                                             circle, boxObject);
        const bool expected = judged.expected;
        if (MyCollision::checkCircleBox(&circle, &boxObject) != expected)
        {
            ADD_FAILURE() << "random case " << index << " (seed " << variant.seed
                          << "): a circle and a box "
                          << (expected ? "that overlap" : "that do not overlap")
                          << " were reported as " << (expected ? "not colliding" : "colliding")
                          << ": circle object = " << describe(&circle)
                          << ", box object = " << describe(&boxObject) << judged.note;
            return;
        }
    }
}

} // namespace conformance
