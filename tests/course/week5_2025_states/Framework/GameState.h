#pragma once

// Game State Class
// Simple game state controller. The enum lists the possible game states (can be modified);
// the class tracks and updates the current state. The student added GAME_OVER.

enum class State { MENU, LEVEL, PAUSE, CREDITS, GAME_OVER };

class GameState
{
public:
	void setCurrentState(State s);
	State getCurrentState();

protected:
	State m_currentState;
};
