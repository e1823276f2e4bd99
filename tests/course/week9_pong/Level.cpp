#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in)
{
	window = hwnd;
	input = in;

	leftPaddle.setUpKey(sf::Keyboard::W);
	leftPaddle.setDownKey(sf::Keyboard::S);
	leftPaddle.setPosition(60, 337);
	leftPaddle.setInput(input);
	leftPaddle.setWindow(window);

	rightPaddle.setUpKey(sf::Keyboard::Up);
	rightPaddle.setDownKey(sf::Keyboard::Down);
	rightPaddle.setPosition(1140, 337);
	rightPaddle.setInput(input);
	rightPaddle.setWindow(window);

	ball.setWindow(window);
	ball.serve(1);

	centreLine.setSize(sf::Vector2f(4, 675));
	centreLine.setPosition(598, 0);
	centreLine.setFillColor(sf::Color(255, 255, 255, 120));

	leftScore = 0;
	rightScore = 0;
}

Level::~Level()
{
}

void Level::handleInput(float dt)
{
	leftPaddle.handleInput(dt);
	rightPaddle.handleInput(dt);
}

void Level::update(float dt)
{
	leftPaddle.update(dt);
	rightPaddle.update(dt);
	ball.update(dt);

	if (Collision::checkBoundingBox(&ball, &leftPaddle))
		ball.collisionResponse(&leftPaddle);
	if (Collision::checkBoundingBox(&ball, &rightPaddle))
		ball.collisionResponse(&rightPaddle);

	if (ball.getPosition().x < 0)
	{
		rightScore++;
		ball.serve(-1);
	}
	else if (ball.getPosition().x > window->getSize().x)
	{
		leftScore++;
		ball.serve(1);
	}
}

void Level::render()
{
	beginDraw();
	window->draw(centreLine);
	window->draw(leftPaddle);
	window->draw(rightPaddle);
	window->draw(ball);
	endDraw();
}
