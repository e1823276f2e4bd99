#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in, GameState* gs, AudioManager* aud)
{
	window = hwnd;
	input = in;
	gameState = gs;
	audio = aud;

	audio->addSound("sfx/bounce.wav", "bounce");
	audio->addMusic("sfx/theme.wav", "theme");
	audio->playMusicbyName("theme");

	ball.setSize(sf::Vector2f(60, 60));
	ball.setPosition(100, 300);
	ball.setFillColor(sf::Color::Yellow);
	ball.setVelocity(1200, 0);
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
	ball.move(ball.getVelocity() * dt);
	float right = window->getSize().x - ball.getSize().x;
	if ((ball.getPosition().x < 0 && ball.getVelocity().x < 0) || (ball.getPosition().x > right && ball.getVelocity().x > 0))
	{
		ball.setVelocity(-ball.getVelocity().x, 0);
		audio->playSoundbyName("bounce");
	}
}

void Level::render()
{
	beginDraw();
	window->draw(ball);
	endDraw();
}
