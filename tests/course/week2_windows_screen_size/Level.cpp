#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in)
{
	window = hwnd;
	input = in;

	// A square in the middle of the window, whatever size the screen made it.
	sf::Vector2u size = window->getSize();
	std::cout << "window " << size.x << " x " << size.y << std::endl;
	rect.setSize(sf::Vector2f(size.x / 4, size.y / 4));
	rect.setOrigin(rect.getSize() / 2.f);
	rect.setPosition(size.x / 2, size.y / 2);
	rect.setFillColor(sf::Color::Red);
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
	rect.rotate(90 * dt);
}

void Level::render()
{
	window->clear(sf::Color(100, 149, 237));
	window->draw(rect);
	window->display();
}
