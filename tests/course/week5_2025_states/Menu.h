#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/BaseLevel.h"
#include "Framework/GameState.h"

// The title screen: Enter (or two seconds) starts the level.
class Menu : public BaseLevel {
public:
	Menu(sf::RenderWindow& window, Input& input, GameState& gameState);

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;

private:
	sf::Font m_font;
	sf::Text m_title;
	float m_shownFor = 0.f;
};
