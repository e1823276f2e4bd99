#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/BaseLevel.h"
#include "Framework/GameObject.h"
#include "Framework/Collision.h"
#include "Framework/GameState.h"
#include "Framework/AudioManager.h"

// A ball bounces between two walls, with a sound on every bounce. After six bounces it is
// game over (the state the student added to GameState.h).
class Level : public BaseLevel {
public:
	Level(sf::RenderWindow* hwnd, Input* in, GameState* gs, AudioManager* aud);
	~Level();

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;
	void renderGameOver();

private:
	GameObject ball;
	GameObject leftWall;
	GameObject rightWall;
	int bounces;
};
