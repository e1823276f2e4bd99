#pragma once
#include "Framework/GameObject.h"
#include "Framework/Animation.h"

// The player: arrow keys (by Scancode) move it, and it animates while it moves.
class Player : public GameObject
{
public:
	Player();

	void handleInput(float dt) override;
	void update(float dt) override;
	void collisionResponse(GameObject& collider) override;

private:
	Animation m_walk;
	float m_speed = 300.f;
};
