#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/Input.h"
#include "Framework/Collision.h"
#include "Ball.h"
#include <string>
#include <iostream>

class Level {
public:
	Level(sf::RenderWindow* hwnd, Input* in);
	~Level();

	void handleInput(float dt);
	void update(float dt);
	void render();

private:
	void beginDraw();
	void endDraw();

	sf::RenderWindow* window;
	Input* input;

	sf::Texture ballTexture;
	Ball ball1;
	Ball ball2;
};
