#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in, GameState* gs, AudioManager* aud)
{
	window = hwnd;
	input = in;
	gameState = gs;
	audio = aud;

	audio->addSound("sfx/bounce.wav", "bounce");
	audio->addMusic("sfx/theme.wav", "theme");

	ball.setSize(sf::Vector2f(50, 50));
	ball.setPosition(575, 300);
	ball.setFillColor(sf::Color::Red);
	ball.setVelocity(900, 0);

	leftWall.setSize(sf::Vector2f(40, 400));
	leftWall.setPosition(100, 125);
	leftWall.setFillColor(sf::Color::Black);
	rightWall.setSize(sf::Vector2f(40, 400));
	rightWall.setPosition(1060, 125);
	rightWall.setFillColor(sf::Color::Black);

	bounces = 0;
}

Level::~Level()
{
	audio->stopAllSounds();
	audio->stopAllMusic();
}

void Level::handleInput(float dt)
{
	if (input->isKeyDown(sf::Keyboard::Escape))
		window->close();
}

void Level::update(float dt)
{
	ball.move(ball.getVelocity() * dt);
	if (Collision::checkBoundingBox(&ball, &leftWall) || Collision::checkBoundingBox(&ball, &rightWall))
	{
		sf::Vector2f velocity = ball.getVelocity();
		ball.setVelocity(-velocity.x, velocity.y);
		ball.move(ball.getVelocity() * dt);
		audio->playSoundbyName("bounce");
		audio->getSound("bounce")->setPitch(1.0f + bounces * 0.1f);
		bounces++;
	}
	if (bounces >= 6)
	{
		audio->stopAllMusic();
		gameState->setCurrentState(State::GAME_OVER);
	}
}

void Level::render()
{
	beginDraw();
	window->draw(leftWall);
	window->draw(rightWall);
	window->draw(ball);
	endDraw();
}

void Level::renderGameOver()
{
	window->clear(sf::Color(80, 0, 0));
	window->draw(leftWall);
	window->draw(ball);
	window->display();
}
