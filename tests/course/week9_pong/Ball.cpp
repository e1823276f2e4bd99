#include "Ball.h"

Ball::Ball()
{
	setSize(sf::Vector2f(18, 18));
	setOrigin(9, 9);
	setCollisionBox(-9, -9, 18, 18);
	setFillColor(sf::Color::Yellow);
	speed = 420;
}

Ball::~Ball()
{
}

void Ball::serve(int direction)
{
	setPosition(600, 337);
	velocity = sf::Vector2f(direction * speed * 0.8f, speed * 0.6f);
}

void Ball::update(float dt)
{
	move(velocity * dt);

	// Bounce off the top and bottom of the window.
	float halfSize = getSize().y / 2;
	if (getPosition().y < halfSize && velocity.y < 0)
		velocity.y = -velocity.y;
	if (getPosition().y > window->getSize().y - halfSize && velocity.y > 0)
		velocity.y = -velocity.y;
}

void Ball::collisionResponse(GameObject* collider)
{
	// Send the ball back towards the other side, a little faster (pow without <cmath>,
	// as Windows lab code does).
	float currentSpeed = sqrt(pow(velocity.x, 2) + pow(velocity.y, 2));
	float newSpeed = currentSpeed * 1.05f;
	if (collider->getPosition().x < 600)
		velocity.x = fabs(velocity.x);
	else
		velocity.x = -fabs(velocity.x);
	velocity = velocity / currentSpeed * newSpeed;
}
