#pragma once

#include <SFML/Graphics.hpp>
#include "Framework/BaseLevel.h"
#include "Framework/Collision.h"
#include "Ball.h"
#include "Physics.h"

class Level : public BaseLevel {
public:
	Level(sf::RenderWindow* hwnd, Input* in);
	~Level();

	void handleInput(float dt) override;
	void update(float dt) override;
	void render() override;

private:
	// A member named like its type: Visual Studio accepts it, g++ needs -fpermissive.
	Ball Ball;
	GameObject target;
	Collision myCollision;
	Physics physics;
	float timeSinceReport;
};
