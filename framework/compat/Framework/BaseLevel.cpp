#include "Framework/BaseLevel.h"

const sf::Color BaseLevel::backgroundColor(100, 149, 237);

BaseLevel::BaseLevel(sf::RenderWindow* hwnd, Input* in, GameState* gs, AudioManager* aud)
    : window(hwnd), input(in), gameState(gs), audio(aud)
{
}

void BaseLevel::beginDraw()
{
    if (window != nullptr)
        window->clear(backgroundColor);
}

void BaseLevel::endDraw()
{
    if (window != nullptr)
        window->display();
}
