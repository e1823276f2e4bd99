#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in)
{
	window = hwnd;
	input = in;

	// gfx/ is found because the program runs from the lab folder.
	if (!ballTexture.loadFromFile("gfx/beach_ball.png"))
		std::cout << "Could not load gfx/beach_ball.png" << std::endl;

	ball1.setTexture(&ballTexture);
	ball1.setSize(sf::Vector2f(64, 64));
	ball1.setCollisionBox(sf::FloatRect(0, 0, 64, 64));
	ball1.setPosition(100, 300);
	ball1.setVelocity(250, 0);
	ball1.setWindow(window);

	ball2.setTexture(&ballTexture);
	ball2.setSize(sf::Vector2f(64, 64));
	ball2.setCollisionBox(sf::FloatRect(0, 0, 64, 64));
	ball2.setPosition(1000, 300);
	ball2.setVelocity(-250, 0);
	ball2.setWindow(window);
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
	ball1.update(dt);
	ball2.update(dt);

	if (Collision::checkBoundingCircle(&ball1, &ball2))
	{
		ball1.collisionResponse(NULL);
		ball2.collisionResponse(NULL);
	}
}

void Level::render()
{
	beginDraw();
	window->draw(ball1);
	window->draw(ball2);
	endDraw();
}

void Level::beginDraw()
{
	window->clear(sf::Color(100, 149, 237));
}

void Level::endDraw()
{
	window->display();
}
