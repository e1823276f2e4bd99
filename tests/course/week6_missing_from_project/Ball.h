#pragma once
#include "Framework/GameObject.h"

// A ball that crosses the window and wraps round.
class Ball : public GameObject
{
public:
	Ball(float speed);
	~Ball();

	void update(float dt) override;
};
