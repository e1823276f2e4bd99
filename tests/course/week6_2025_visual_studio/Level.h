#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/baselevel.h"
#include "Framework/collision.h"
#include "ball.h"

class Level : BaseLevel {
public:
	Level(sf::RenderWindow& window, Input& input);

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;

private:
	sf::Texture m_ballTexture;
	// A member named like its type: Visual Studio accepts it.
	Ball Ball;
	GameObject m_block;
	sf::Font m_font;
	sf::Text m_score;
};
