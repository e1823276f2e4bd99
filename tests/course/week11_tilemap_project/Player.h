#pragma once
#include "Framework/gameobject.h"

// A ball that falls onto the tiles and rolls left and right between the ends of the level.
class Player : public GameObject
{
public:
	Player();
	~Player();

	void update(float dt) override;
	void collisionResponse(GameObject* collider) override;

private:
	float gravity;
};
