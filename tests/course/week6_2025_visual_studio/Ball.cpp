#include "ball.h"

Ball::Ball()
{
	setSize({ 64, 64 });
	setCollisionBox(0, 0, 64, 64);
	setCollider(true);
	m_velocity = { 260, 190 };
}

void Ball::update(float dt)
{
	move(m_velocity * dt);
	sf::Vector2u size = m_window->getSize();
	if ((getPosition().x < 0 && m_velocity.x < 0) || (getPosition().x + getSize().x > size.x && m_velocity.x > 0))
	{
		m_velocity.x = -m_velocity.x;
		m_bounces++;
	}
	if ((getPosition().y < 0 && m_velocity.y < 0) || (getPosition().y + getSize().y > size.y && m_velocity.y > 0))
	{
		m_velocity.y = -m_velocity.y;
		m_bounces++;
	}
}
