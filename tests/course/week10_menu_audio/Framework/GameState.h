#pragma once

// Game State Class
// Simple game state controller. Enum lists possible game states (can be modified), tracks and updates the current state
// Paul Robertson 2017 - the course's header, with a state added by the student for the lab.

enum class State { MENU, LEVEL, PAUSE, CREDITS, GAME_OVER };

class GameState
{
public:
	void setCurrentState(State s);
	State getCurrentState();

protected:
	State currentState;
};
