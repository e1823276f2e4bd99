#include "Framework/BaseLevel.h"

BaseLevel::BaseLevel(sf::RenderWindow& window, Input& input)
    : m_window(window), m_input(input), m_gameState(m_ownGameState)
{
}

BaseLevel::BaseLevel(sf::RenderWindow& window, Input& input, GameState& gameState)
    : m_window(window), m_input(input), m_gameState(gameState)
{
}

void BaseLevel::beginDraw()
{
    m_window.clear(sf::Color(100, 149, 237));
}

void BaseLevel::endDraw()
{
    m_window.display();
}
