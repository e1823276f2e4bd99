#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/BaseLevel.h"
#include "Framework/TileMap.h"
#include "Framework/Collision.h"
#include "Framework/AudioManager.h"
#include "Framework/GameState.h"

// Week 5: a tile map to land on, and game states (P pauses, Escape goes back to the menu).
class Level : public BaseLevel {
public:
	Level(sf::RenderWindow& window, Input& input, GameState& gameState);
	~Level() override = default;

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;

private:
	TileMap m_tileMap;
	sf::Texture m_tileTexture;
	GameObject m_player;
	AudioManager m_audio;
	bool m_onGround = false;
	float m_gravity = 900.f;
};
