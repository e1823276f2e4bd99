#include "Player.h"

Player::Player()
{
	for (int i = 0; i < 4; i++)
		m_walk.addFrame(sf::IntRect({ i * 32, 0 }, { 32, 32 }));
	m_walk.setFrameSpeed(1.f / 8.f);
	setSize({ 96, 96 });
	setOrigin({ 48, 48 });
	setCollisionBox(-48, -48, 96, 96);
	setCollider(true);
}

void Player::handleInput(float dt)
{
	m_velocity = { 0, 0 };
	if (m_input->isKeyDown(sf::Keyboard::Scancode::Left)) m_velocity.x = -m_speed;
	if (m_input->isKeyDown(sf::Keyboard::Scancode::Right)) m_velocity.x = m_speed;
	if (m_input->isKeyDown(sf::Keyboard::Scancode::Up)) m_velocity.y = -m_speed;
	if (m_input->isKeyDown(sf::Keyboard::Scancode::Down)) m_velocity.y = m_speed;
	if (m_input->isPressed(sf::Keyboard::Scancode::F)) m_walk.setFlipped(!m_walk.getFlipped());
}

void Player::update(float dt)
{
	move(m_velocity * dt);
	m_walk.animate(dt);
	setTextureRect(m_walk.getCurrentFrame());
}

void Player::collisionResponse(GameObject& collider)
{
	setFillColor(sf::Color::Red);
}
