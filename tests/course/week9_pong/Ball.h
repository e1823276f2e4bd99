#pragma once
#include "Framework\GameObject.h"

class Ball : public GameObject
{
public:
	Ball();
	~Ball();

	void serve(int direction);
	void update(float dt) override;
	void collisionResponse(GameObject* collider) override;

private:
	float speed;
};
