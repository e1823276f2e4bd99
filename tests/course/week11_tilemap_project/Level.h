#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/Input.h"
#include "Framework/tilemap.h"
#include "Framework/collision.h"
#include "player.h"
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
	sf::RenderWindow* window;
	Input* input;

	TileMap tileMap;
	sf::Texture ballTexture;
	Player player;
};
