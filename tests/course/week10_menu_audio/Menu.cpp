#include "Menu.h"

Menu::Menu(sf::RenderWindow* hwnd, Input* in, GameState* gs, AudioManager* aud)
	: BaseLevel(hwnd, in, gs, aud)
{
	title.setSize(sf::Vector2f(600, 120));
	title.setOrigin(300, 60);
	title.setPosition(600, 200);
	title.setFillColor(sf::Color(255, 200, 0));
	timeOnMenu = 0;
}

Menu::~Menu()
{
}

void Menu::handleInput(float dt)
{
	if (input->isKeyDown(sf::Keyboard::Enter))
	{
		input->setKeyUp(sf::Keyboard::Enter);
		gameState->setCurrentState(State::LEVEL);
	}
}

void Menu::update(float dt)
{
	timeOnMenu += dt;
	title.setScale(1 + 0.1f * sin(timeOnMenu * 4), 1);
	if (timeOnMenu > 2)
	{
		audio->playMusicbyName("theme");
		gameState->setCurrentState(State::LEVEL);
	}
}

void Menu::render()
{
	beginDraw();
	window->draw(title);
	endDraw();
}
