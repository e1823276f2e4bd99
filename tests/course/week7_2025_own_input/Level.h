#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/BaseLevel.h"
#include "Framework/Collision.h"

// A menu button that lights up while the mouse holds it down. It relies on this lab's edited
// Framework/Input.cpp, where isLeftMousePressed() stays true while the button is held.
class Level : public BaseLevel {
public:
	Level(sf::RenderWindow& window, Input& input);

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;

private:
	GameObject m_button;
	sf::Font m_font;
	sf::Text m_label;
	int m_framesHeld = 0;
};
