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

	// Bounce off the left and right edges of the window.
	sf::Vector2u windowSize = window->getSize();
	if (getPosition().x < 0 && velocity.x < 0)
		velocity.x = -velocity.x;
	if (getPosition().x + getSize().x > windowSize.x && velocity.x > 0)
		velocity.x = -velocity.x;
}

void Ball::collisionResponse(GameObject* collider)
{
	// Hit the other ball: go back the way we came.
	velocity.x = -velocity.x;
}
