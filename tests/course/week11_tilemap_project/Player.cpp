#include "player.h"

Player::Player()
{
	gravity = 600;
}

Player::~Player()
{
}

void Player::update(float dt)
{
	velocity.y += gravity * dt;
	move(velocity * dt);

	if (getPosition().x < 0 && velocity.x < 0)
		velocity.x = -velocity.x;
	if (getPosition().x + getSize().x > 1200 && velocity.x > 0)
		velocity.x = -velocity.x;
}

void Player::collisionResponse(GameObject* collider)
{
	// Landed on a tile: sit on top of it.
	sf::FloatRect tile = collider->getCollisionBox();
	if (velocity.y > 0)
	{
		setPosition(getPosition().x, tile.top - getSize().y);
		velocity.y = 0;
	}
}
