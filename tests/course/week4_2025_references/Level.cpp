#include "Level.h"
#include <iostream>

Level::Level(sf::RenderWindow& hwnd, Input& in) :
	BaseLevel(hwnd, in), m_text(m_font)
{
	if (!m_playerTexture.loadFromFile("gfx/Player_Sheet.png"))
		std::cerr << "could not load gfx/Player_Sheet.png\n";
	m_player.setTexture(&m_playerTexture);
	m_player.setPosition({ 300, 300 });
	m_player.setInput(&m_input);
	m_player.setWindow(&m_window);

	m_wall.setSize({ 60, 400 });
	m_wall.setPosition({ 700, 140 });
	m_wall.setFillColor(sf::Color::Black);
	m_wall.setCollider(true);

	m_coin.setSize({ 40, 40 });
	m_coin.setPosition({ 500, 500 });
	m_coin.setFillColor(sf::Color::Yellow);
	m_coin.setCollider(true);

	if (m_font.openFromFile("font/DejaVuSans.ttf"))
		m_text.setString("Arrow keys move; F flips");
}

void Level::handleInput(float dt)
{
	if (m_input.isKeyDown(sf::Keyboard::Scancode::Escape))
		m_window.close();
	m_player.handleInput(dt);
	if (m_input.isLeftMousePressed() && Collision::checkBoundingBox(m_coin, sf::Vector2i(m_input.getMouseX(), m_input.getMouseY())))
		m_coin.setAlive(false);
}

void Level::update(float dt)
{
	m_player.update(dt);
	m_player.setFillColor(sf::Color::White);
	if (Collision::checkBoundingBox(m_player, m_wall))
		m_player.collisionResponse(m_wall);
	if (m_coin.isAlive() && Collision::checkBoundingCircle(m_player, m_coin))
		m_coin.setAlive(false);
}

void Level::render()
{
	beginDraw();
	m_window.draw(m_wall);
	if (m_coin.isAlive())
		m_window.draw(m_coin);
	m_window.draw(m_player);
	m_window.draw(m_text);
	endDraw();
}
