#include "Ball.h"

Ball::Ball(float speed)
{
	setSize(sf::Vector2f(50, 50));
	setFillColor(sf::Color::Red);
	setVelocity(speed, 0);
}

Ball::~Ball()
{
}

void Ball::update(float dt)
{
	move(velocity * dt);
	if (getPosition().x > window->getSize().x)
		setPosition(-getSize().x, getPosition().y);
}
