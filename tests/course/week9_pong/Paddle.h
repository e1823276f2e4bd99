#pragma once
#include "Framework\GameObject.h"

class Paddle : public GameObject
{
public:
	Paddle();
	~Paddle();

	void setUpKey(int key) { upKey = key; }
	void setDownKey(int key) { downKey = key; }

	void handleInput(float dt) override;
	void update(float dt) override;

private:
	int upKey;
	int downKey;
	float speed;
};
