#include "Level.h"

Level::Level(sf::RenderWindow& hwnd, Input& in, GameState& gs) :
	BaseLevel(hwnd, in, gs)
{
	m_tileMap.loadTexture("gfx/tiles.png");
	std::vector<GameObject> tiles;
	for (int i = 0; i < 3; i++)
	{
		GameObject tile;
		tile.setSize({ 32, 32 });
		tile.setCollider(true);
		tile.setTextureRect(sf::IntRect({ i * 32, 0 }, { 32, 32 }));
		tiles.push_back(tile);
	}
	tiles[0].setCollider(false);	// the blank tile
	m_tileMap.setTileSet(tiles);

	// 38 across, 5 down: a ledge on the left, a floor of grass over brick.
	sf::Vector2u mapSize(38, 5);
	std::vector<int> map;
	for (unsigned int row = 0; row < mapSize.y; row++)
		for (unsigned int column = 0; column < mapSize.x; column++)
		{
			if (row == 0) map.push_back(column > 4 && column < 12 ? 1 : 0);
			else if (row == 1) map.push_back(column > 4 && column < 12 ? 2 : 0);
			else if (row == 3) map.push_back(1);
			else if (row == 4) map.push_back(2);
			else map.push_back(0);
		}
	m_tileMap.setTileMap(map, mapSize);
	m_tileMap.setPosition({ 0, 515 });
	m_tileMap.buildLevel();

	m_player.setSize({ 40, 56 });
	m_player.setFillColor(sf::Color::Red);
	m_player.setPosition({ 220, 200 });
	m_player.setCollider(true);

	m_audio.addSound("sfx/land.wav", "land");
}

void Level::handleInput(float dt)
{
	if (m_input.isPressed(sf::Keyboard::Scancode::Escape))
		m_gameState.setCurrentState(State::MENU);
	if (m_input.isPressed(sf::Keyboard::Scancode::P))
		m_gameState.setCurrentState(State::PAUSE);
	sf::Vector2f velocity = m_player.getVelocity();
	velocity.x = 0;
	if (m_input.isKeyDown(sf::Keyboard::Scancode::Left)) velocity.x = -250;
	if (m_input.isKeyDown(sf::Keyboard::Scancode::Right)) velocity.x = 250;
	if (m_onGround && m_input.isPressed(sf::Keyboard::Scancode::Space)) velocity.y = -500;
	m_player.setVelocity(velocity);
}

void Level::update(float dt)
{
	sf::Vector2f velocity = m_player.getVelocity();
	velocity.y += m_gravity * dt;
	m_player.setVelocity(velocity);
	m_player.move(velocity * dt);

	bool wasOnGround = m_onGround;
	m_onGround = false;
	for (GameObject& tile : m_tileMap.getLevel())
	{
		if (tile.isCollider() && Collision::checkBoundingBox(m_player, tile) && m_player.getVelocity().y > 0)
		{
			// land on top of the tile
			m_player.setPosition({ m_player.getPosition().x, tile.getPosition().y - m_player.getSize().y });
			m_player.setVelocity(m_player.getVelocity().x, 0);
			m_onGround = true;
		}
	}
	if (m_onGround && !wasOnGround)
		m_audio.playSoundbyName("land");
}

void Level::render()
{
	beginDraw();
	m_tileMap.render(m_window);
	m_window.draw(m_player);
	endDraw();
}
