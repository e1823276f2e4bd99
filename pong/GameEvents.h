// GameEvents.h - what happened during one simulation step, for the sound layer to play.
//
// The simulation never plays a sound itself: it only writes down what happened. Whoever wants
// to react (Sounds.cpp, a test, a replay) reads the list. So the rules run the same with or
// without an audio device, and a test can check "the ball hit the wall" by reading events.
#pragma once

enum class GameEvent
{
    PaddleHit, // the ball bounced off a paddle
    WallHit,   // the ball bounced off the top or bottom wall
    Point,     // the ball left the arena: someone scored
    MatchWon   // that point ended the match
};
