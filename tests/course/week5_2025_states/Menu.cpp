#include "Menu.h"

Menu::Menu(sf::RenderWindow& hwnd, Input& in, GameState& gs) :
	BaseLevel(hwnd, in, gs), m_title(m_font)
{
	if (m_font.openFromFile("font/DejaVuSans.ttf"))
		m_title.setString("Week 5 - press Enter");
	m_title.setCharacterSize(48);
	m_title.setPosition({ 400, 300 });
}

void Menu::handleInput(float dt)
{
	if (m_input.isPressed(sf::Keyboard::Scancode::Enter))
		m_gameState.setCurrentState(State::LEVEL);
}

void Menu::update(float dt)
{
	m_shownFor += dt;
	if (m_shownFor > 2.f)
	{
		m_shownFor = 0.f;
		m_gameState.setCurrentState(State::LEVEL);
	}
}

void Menu::render()
{
	beginDraw();
	m_window.draw(m_title);
	endDraw();
}
