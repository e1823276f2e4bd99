#include "hitbox/course/BaseLevel.h"

const sf::Color BaseLevel::backgroundColor(100, 149, 237);

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
