#include "level.h"

Level::Level(sf::RenderWindow* hwnd, Input* in)
{
	window = hwnd;
	input = in;

	// The file is gfx/Beach_Ball.png: Windows does not mind the small b.
	if (!ballTexture.loadFromFile("gfx/Beach_ball.png"))
		std::cout << "could not load gfx/Beach_ball.png" << std::endl;
	player.setTexture(&ballTexture);
	player.setSize(sf::Vector2f(64, 64));
	player.setCollisionBox(0, 0, 64, 64);
	player.setPosition(100, 100);
	player.setVelocity(200, 0);

	tileMap.loadTexture("gfx/marioTiles.png");
	GameObject tile;
	std::vector<GameObject> tiles;
	for (int i = 0; i < 3; i++)
	{
		tile.setSize(sf::Vector2f(32, 32));
		tile.setCollisionBox(0, 0, 32, 32);
		tile.setCollider(true);
		tiles.push_back(tile);
	}
	tiles[0].setCollider(false);
	tiles[0].setTextureRect(sf::IntRect(0, 0, 32, 32));
	tiles[1].setTextureRect(sf::IntRect(32, 0, 32, 32));
	tiles[2].setTextureRect(sf::IntRect(64, 0, 32, 32));
	tileMap.setTileSet(tiles);

	// 38 tiles across, 4 down: a floor of grass over brick, with a step in the middle.
	sf::Vector2u mapSize(38, 4);
	std::vector<int> map;
	for (unsigned int row = 0; row < mapSize.y; row++)
		for (unsigned int column = 0; column < mapSize.x; column++)
		{
			if (row == 0)
				map.push_back(column > 15 && column < 22 ? 1 : 0);
			else if (row == 1)
				map.push_back(column > 15 && column < 22 ? 2 : 1);
			else
				map.push_back(2);
		}
	tileMap.setTileMap(map, mapSize);
	tileMap.setPosition(sf::Vector2f(0, 547));
	tileMap.buildLevel();
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
	player.update(dt);

	std::vector<GameObject>* world = tileMap.getLevel();
	for (int i = 0; i < (int)world->size(); i++)
	{
		if ((*world)[i].isCollider() && Collision::checkBoundingBox(&player, &(*world)[i]))
			player.collisionResponse(&(*world)[i]);
	}
}

void Level::render()
{
	window->clear(sf::Color(100, 149, 237));
	tileMap.render(window);
	window->draw(player);
	window->display();
}
