#include "Paddle.h"

Paddle::Paddle()
{
	setSize(sf::Vector2f(20, 110));
	setOrigin(10, 55);
	setCollisionBox(-10, -55, 20, 110);
	setFillColor(sf::Color::White);
	upKey = sf::Keyboard::W;
	downKey = sf::Keyboard::S;
	speed = 500;
}

Paddle::~Paddle()
{
}

void Paddle::handleInput(float dt)
{
	velocity.y = 0;
	if (input->isKeyDown(upKey))
		velocity.y = -speed;
	if (input->isKeyDown(downKey))
		velocity.y = speed;
}

void Paddle::update(float dt)
{
	move(velocity * dt);

	// Keep the paddle on the screen.
	float halfHeight = getSize().y / 2;
	if (getPosition().y < halfHeight)
		setPosition(getPosition().x, halfHeight);
	if (getPosition().y > window->getSize().y - halfHeight)
		setPosition(getPosition().x, window->getSize().y - halfHeight);
}
