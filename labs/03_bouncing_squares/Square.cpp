#include "Square.h"

#include "hitbox/geometry/Vec2.h"
#include "hitbox/objects/Collision.h"
#include "hitbox/sfml/Conversions.h"
// Your own class from lab 0: README.md, "Using your own Collision class from lab 0".
#include "MyCollision.h"

#include <algorithm>
#include <cmath>

namespace
{
// Seconds a hit flash takes to fade.
constexpr float flashSeconds = 0.25f;
} // namespace

Square::Square(sf::Vector2f center, sf::Vector2f startVelocity, sf::Color color)
{
    // [slide:lab03-collision-box]
    // The shape is the whole picture; its origin, the point getPosition() gives, is the
    // centre of the picture.
    setSize({spriteSize, spriteSize});
    setOrigin({spriteSize / 2.f, spriteSize / 2.f});
    // BEGIN TASK 1: fit the collision box to the crate
    // Without this the box is the whole picture, margin and all, and squares bounce off
    // each other with a visible gap. The box is measured from the origin (the centre):
    // it starts half a crate up and to the left of it.
    setCollisionBox(-crateSize / 2.f, -crateSize / 2.f, crateSize, crateSize);
    // END TASK 1
    // [/slide]
    setPosition(center);
    setFillColor(color);
    setVelocity(startVelocity);
}

void Square::update(float dt)
{
    move(velocity * dt);
    flash = std::max(0.f, flash - dt / flashSeconds);

    // BEGIN TASK 2: bounce the collision box off the window edges
    // Test the collision box, not the picture: the see-through margin may go past the
    // edge, the crate may not. Move the square back by however far the box is out.
    const hitbox::Box box = hitbox::toBox(getCollisionBox());
    bool hitWall = false;
    if (box.left < 0.f || box.left + box.width > worldSize.x)
    {
        const bool outLeft = box.left < 0.f;
        move({outLeft ? -box.left : worldSize.x - (box.left + box.width), 0.f});
        velocity.x = outLeft ? std::abs(velocity.x) : -std::abs(velocity.x);
        hitWall = true;
    }
    if (box.top < 0.f || box.top + box.height > worldSize.y)
    {
        const bool outTop = box.top < 0.f;
        move({0.f, outTop ? -box.top : worldSize.y - (box.top + box.height)});
        velocity.y = outTop ? std::abs(velocity.y) : -std::abs(velocity.y);
        hitWall = true;
    }
    if (hitWall)
        collisionResponse(nullptr);
    // END TASK 2
}

void Square::collisionResponse(hitbox::GameObject*)
{
    ++hitCount;
    flash = 1.f;
}

void Square::setWorldSize(sf::Vector2f size)
{
    worldSize = size;
}

int Square::getHitCount() const
{
    return hitCount;
}

float Square::getFlash() const
{
    return flash;
}

// [slide:lab03-aabb-response]
void bounceApart(Square& first, Square& second)
{
    // BEGIN TASK 3: bounce squares off each other, box against box
    if (!hitbox::Collision::checkBoundingBox(&first, &second))
        return;
    first.collisionResponse(&second);
    second.collisionResponse(&first);
    // For boxes the normal is an axis, (+-1, 0) or (0, +-1): the way out that is
    // shortest. Each square moves half the overlap, so afterwards they just touch.
    const hitbox::Contact contact = hitbox::Collision::getBoundingBoxContact(&first, &second);
    const hitbox::Vec2 normal = contact.normal;
    first.move(hitbox::toSfml(normal * (contact.depth / 2.f)));
    second.move(hitbox::toSfml(-normal * (contact.depth / 2.f)));
    // Equal crates swap their velocities along the normal; along the other axis
    // nothing changes. Squares already moving apart are left alone.
    const hitbox::Vec2 relative = hitbox::toVec2(first.getVelocity() - second.getVelocity());
    const float closing = hitbox::dot(relative, normal);
    if (closing < 0.f)
    {
        first.setVelocity(first.getVelocity() - hitbox::toSfml(normal * closing));
        second.setVelocity(second.getVelocity() + hitbox::toSfml(normal * closing));
    }
    // STARTER TASK 3
    // (void)first;
    // (void)second;
    // END TASK 3
}
// [/slide]
