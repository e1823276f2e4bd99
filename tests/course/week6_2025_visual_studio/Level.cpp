#include "Level.h"

Level::Level(sf::RenderWindow& hwnd, Input& in) :
	BaseLevel(hwnd, in), m_score(m_font)
{
	// The file is gfx/Ball.png: Windows does not mind the small letters.
	if (!m_ballTexture.loadFromFile("gfx/ball.PNG"))
		std::cout << "could not load gfx/ball.PNG\n";
	Ball.setTexture(&m_ballTexture);
	Ball.setPosition({ 100, 100 });
	Ball.setWindow(&m_window);

	m_block.setSize({ 300, 80 });
	m_block.setPosition({ 450, 300 });
	m_block.setFillColor(sf::Color(40, 40, 40));
	m_block.setCollider(true);

	if (!m_font.openFromFile("font/DejaVuSans.ttf"))
		std::cout << "could not load the font\n";
	m_score.setPosition({ 20, 20 });
}

void Level::handleInput(float dt)
{
	if (m_input.isPressed(sf::Keyboard::Scancode::Escape))
		m_window.close();
}

void Level::update(float dt)
{
	Ball.update(dt);
	m_block.setFillColor(Collision::checkBoundingBox(Ball, m_block) ? sf::Color::Red : sf::Color(40, 40, 40));

	// No <sstream>: Visual Studio's headers bring it along.
	std::stringstream text;
	text << "Bounces: " << Ball.getBounces() << "  distance to block: " << std::setprecision(3)
		<< std::sqrt(pow(Ball.getPosition().x - m_block.getPosition().x, 2) + pow(Ball.getPosition().y - m_block.getPosition().y, 2));
	m_score.setString(text.str());
}

void Level::render()
{
	beginDraw();
	m_window.draw(m_block);
	m_window.draw(Ball);
	m_window.draw(m_score);
	endDraw();
}
