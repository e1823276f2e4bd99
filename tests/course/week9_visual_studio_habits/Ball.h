#pragma once
#include "Framework/GameObject.h"
#include "Framework/Collision.h"

// A ball that is also a Collision (the student's way to call the tests without the
// class name), bouncing off the edges of the window.
class Ball : public GameObject, public Collision
{
public:
	Ball();
	~Ball();

	void update(float dt) override;
	bool touches(GameObject* other);
	std::string describe();
};
