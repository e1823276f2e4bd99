#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/Input.h"
#include "Vector"
#include <String>
#include <IOStream>
#include "score.h"

// Headers spelled as Windows lets a student spell them: "Vector" is <vector>, <String> is
// <string>, "score.h" is this lab's Score.h.
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

	std::vector<sf::CircleShape> dots;
	std::string title;
	Score score;
};
