#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/BaseLevel.h"
#include "Framework/Collision.h"
#include "Player.h"

class Level : BaseLevel {
public:
	Level(sf::RenderWindow& window, Input& input);
	~Level() override = default;

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;

private:
	sf::Texture m_playerTexture;
	Player m_player;
	GameObject m_wall;
	GameObject m_coin;
	sf::Font m_font;
	sf::Text m_text;
};
