#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in)
{
	window = hwnd;
	input = in;
	title = "Week 3: shapes";

	for (int i = 0; i < 10; i++)
	{
		sf::CircleShape dot(30);
		dot.setPosition(100 + i * 100, 300);
		dot.setFillColor(sf::Color(25 * i, 200, 255 - 25 * i));
		dots.push_back(dot);
		score.dots++;
	}
	std::cout << title << ": " << score.dots << " dots" << std::endl;
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
}

void Level::render()
{
	window->clear(sf::Color(100, 149, 237));
	for (int i = 0; i < dots.size(); i++)
		window->draw(dots[i]);
	window->display();
}
