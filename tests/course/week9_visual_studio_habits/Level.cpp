#include "Level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in)
{
	window = hwnd;
	input = in;

	Ball.setSize(sf::Vector2f(64, 64));
	Ball.setFillColor(sf::Color::Yellow);
	Ball.setPosition(100, 100);
	Ball.setVelocity(300, 220);
	Ball.setWindow(window);

	target.setSize(sf::Vector2f(200, 200));
	target.setPosition(500, 240);
	target.setFillColor(sf::Color::Green);

	timeSinceReport = 0;
}

Level::~Level()
{
}

void Level::handleInput(float dt)
{
	if (input->isKeyDown(sf::Keyboard::Escape))
		window->close();
}

void Level::update(float dt)
{
	Ball.update(dt);

	// The same test three ways: through an object of the static class, through the ball
	// (which derives from Collision), and by the class name.
	bool hit = myCollision.checkBoundingBox(&Ball, &target);
	if (hit != Ball.touches(&target) && Collision::checkBoundingCircle(&Ball, &target) != hit)
		std::cout << "box and circle disagree (they may, near the corners)" << std::endl;
	target.setFillColor(hit ? sf::Color::Red : sf::Color::Green);

	timeSinceReport += dt;
	if (timeSinceReport > 1)
	{
		std::cout << "ball at " << Ball.describe() << ", speed " << physics.speed(Ball.getVelocity())
			<< ", " << Physics::distance(Ball.getPosition(), target.getPosition()) << " from the target" << std::endl;
		timeSinceReport = 0;
	}
}

void Level::render()
{
	beginDraw();
	window->draw(target);
	window->draw(Ball);
	endDraw();
}
