#pragma once

#include <SFML\Graphics.hpp>
#include "Framework\BaseLevel.h"
#include "Framework\Collision.h"
#include "Paddle.h"
#include "Ball.h"

class Level : public BaseLevel {
public:
	Level(sf::RenderWindow* hwnd, Input* in);
	~Level();

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;

private:
	Paddle leftPaddle;
	Paddle rightPaddle;
	Ball ball;
	sf::RectangleShape centreLine;
	int leftScore;
	int rightScore;
};
