#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in) : ball(300)
{
	window = hwnd;
	input = in;
	ball.setWindow(window);
	ball.setPosition(0, 300);
}

Level::~Level()
{
}

void Level::handleInput(float dt)
{
	if (input->isKeyDown(sf::Keyboard::Escape))
		window->close();
}

void Level::update(float dt)
{
	ball.update(dt);
}

void Level::render()
{
	window->clear(sf::Color(100, 149, 237));
	window->draw(ball);
	window->display();
}
