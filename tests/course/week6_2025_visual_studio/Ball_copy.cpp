// The student's old copy of Ball.cpp, not in the Visual Studio project: it must not be built.
#include "BallOld.h"

void Ball::update(float dt) { }
