// Bullet.h - a small fast box fired along one lane of the range.
//
// It remembers where it was after every step (the trail) and the area its last step swept
// over, so the picture can show what a discrete test sees and what a swept test sees.
#pragma once

#include "hitbox/objects/GameObject.h"

#include <vector>

// Which test a bullet is checked with. Both lanes fire the same shot at the same speed.
enum class Lane
{
    Discrete, // test where the bullet IS after each step
    Swept     // test the whole move of each step
};

class Bullet : public hitbox::GameObject
{
public:
    Bullet(Lane lane, sf::Vector2f start, float speed);

    Lane getLane() const;
    float getSpeed() const;
    bool isFlying() const; // neither stopped by the wall nor off the range yet
    bool hitTheWall() const;
    void stopInTheWall(); // the test found the wall: it stays where it is
    void flewAway();      // left the range: a miss

    // Move by `step` and remember it (the trail and the swept area of this step).
    void moveBy(sf::Vector2f step);
    const std::vector<sf::Vector2f>& getTrail() const;
    // The smallest box around the bullet's start and end of its last step.
    sf::FloatRect getLastSweptArea() const;

    // Set by the level each step: could this step pass through the wall unseen?
    void setCouldTunnel(bool couldTunnelNow);
    bool couldTunnel() const;

private:
    Lane lane;
    float speed;
    bool flying = true;
    bool stoppedByWall = false;
    bool tunnelWarning = false;
    std::vector<sf::Vector2f> trail;
    sf::FloatRect lastSweptArea;
};
