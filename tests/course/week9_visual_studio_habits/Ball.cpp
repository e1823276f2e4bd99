#include "Ball.h"

Ball::Ball()
{
}

Ball::~Ball()
{
}

void Ball::update(float dt)
{
	move(velocity * dt);

	sf::Vector2u windowSize = window->getSize();
	if (getPosition().x < 0 && velocity.x < 0)
		velocity.x = std::abs(velocity.x);
	if (getPosition().x + getSize().x > windowSize.x && velocity.x > 0)
		velocity.x = -std::abs(velocity.x);
	if (getPosition().y < 0 && velocity.y < 0)
		velocity.y = std::abs(velocity.y);
	if (getPosition().y + getSize().y > windowSize.y && velocity.y > 0)
		velocity.y = -std::abs(velocity.y);
}

bool Ball::touches(GameObject* other)
{
	return checkBoundingCircle(this, other);
}

std::string Ball::describe()
{
	// No <sstream> or <iomanip>: Visual Studio's headers bring them along.
	std::stringstream text;
	text << std::fixed << std::setprecision(1) << getPosition().x << ", " << getPosition().y;
	return text.str();
}
