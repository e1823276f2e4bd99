#include "Level.h"
#include <iostream>

Level::Level(sf::RenderWindow& hwnd, Input& in) :
	BaseLevel(hwnd, in), m_label(m_font)
{
	m_button.setSize({ 600, 300 });
	m_button.setPosition({ 300, 200 });
	m_button.setFillColor(sf::Color(60, 60, 160));
	if (m_font.openFromFile("font/DejaVuSans.ttf"))
		m_label.setString("Hold to start");
	m_label.setPosition({ 480, 320 });
}

void Level::handleInput(float dt)
{
	sf::Vector2i mouse(m_input.getMouseX(), m_input.getMouseY());
	if (m_input.isLeftMousePressed() && Collision::checkBoundingBox(m_button, mouse))
		m_framesHeld++;
	else
		m_framesHeld = 0;
}

void Level::update(float dt)
{
	m_button.setFillColor(m_framesHeld > 0 ? sf::Color(240, 200, 40) : sf::Color(60, 60, 160));
	if (m_framesHeld == 30)
		std::cout << "button held for 30 frames" << std::endl;
}

void Level::render()
{
	beginDraw();
	m_window.draw(m_button);
	m_window.draw(m_label);
	endDraw();
}
