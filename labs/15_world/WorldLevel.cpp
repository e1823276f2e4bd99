#include "WorldLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/BroadphaseDrawing.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/debug/ExplainOverlay.h"
#include "hitbox/geometry/Vec2.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <cmath>
#include <cstdio>

WorldLevel::WorldLevel(unsigned seed) : random(seed)
{
    start();
}

void WorldLevel::start()
{
    removeAllButThePlayer();
    placePlayer(getWorldSize() / 2.f);
    autopilot = true;
    newWaves = true;
    score = 0;
    for (int index = 0; index < startCoins; ++index)
        addRandomCoin();
    for (int index = 0; index < startEnemies; ++index)
        addRandomEnemy();
}

void WorldLevel::removeAllButThePlayer()
{
    // The World points at the objects: empty it before they are destroyed.
    world.clear();
    coins.clear();
    enemies.clear();
    if (!player)
    {
        player = std::make_unique<Player>(getWorldSize() / 2.f);
        player->setName("player");
    }
    player->setWorldSize(getWorldSize());
    player->setVelocity({});
    const Layers layers = layersFor(Kind::Player);
    world.add(*player, layers.layer, layers.mask, hitbox::World::Shape::Box);
    world.setRule(mayMeetNow);
    autopilot = false;
    newWaves = false;
}

void WorldLevel::addCoin(sf::Vector2f center)
{
    coins.push_back(std::make_unique<Coin>(center));
    coins.back()->setName("coin");
    const Layers layers = layersFor(Kind::Coin);
    world.add(*coins.back(), layers.layer, layers.mask, hitbox::World::Shape::Circle);
}

void WorldLevel::addEnemy(sf::Vector2f center, sf::Vector2f velocity)
{
    enemies.push_back(std::make_unique<Enemy>(center, velocity));
    enemies.back()->setName("enemy");
    enemies.back()->setWorldSize(getWorldSize());
    const Layers layers = layersFor(Kind::Enemy);
    world.add(*enemies.back(), layers.layer, layers.mask, hitbox::World::Shape::Box);
}

void WorldLevel::addRandomCoin()
{
    const sf::Vector2f size = getWorldSize();
    std::uniform_real_distribution<float> x(2.f * coinRadius, size.x - 2.f * coinRadius);
    std::uniform_real_distribution<float> y(2.f * coinRadius, size.y - 2.f * coinRadius);
    addCoin({x(random), y(random)});
}

void WorldLevel::addRandomEnemy()
{
    const sf::Vector2f size = getWorldSize();
    std::uniform_real_distribution<float> x(enemySize, size.x - enemySize);
    std::uniform_real_distribution<float> y(enemySize, size.y - enemySize);
    std::uniform_real_distribution<float> angle(0.f, 2.f * hitbox::pi);
    const float direction = angle(random);
    addEnemy({x(random), y(random)},
             {enemySpeed * std::cos(direction), enemySpeed * std::sin(direction)});
}

void WorldLevel::placePlayer(sf::Vector2f center)
{
    player->setPosition(center);
}

void WorldLevel::setAutopilot(bool on)
{
    autopilot = on;
    if (!on)
        player->setVelocity({});
}

void WorldLevel::handleInput(const hitbox::Input& input, float)
{
    mouse = input.getMousePosition();
    if (input.isPressed(sf::Keyboard::Key::R))
        start();
    if (input.isPressed(sf::Keyboard::Key::A))
        autopilot = !autopilot;
    if (input.isPressed(sf::Keyboard::Key::M))
    {
        const int next = (static_cast<int>(world.getMethod()) + 1) % 4; // four methods
        world.setMethod(static_cast<hitbox::BroadphaseMethod>(next));
    }
    steerPlayer(input);
}

// The arrow keys move the player (and switch the autopilot off); the autopilot heads for
// the nearest coin, so a run with no keyboard (--headless, the screenshot) still plays.
void WorldLevel::steerPlayer(const hitbox::Input& input)
{
    sf::Vector2f direction;
    direction.x = (input.isKeyDown(sf::Keyboard::Key::Right) ? 1.f : 0.f) -
                  (input.isKeyDown(sf::Keyboard::Key::Left) ? 1.f : 0.f);
    direction.y = (input.isKeyDown(sf::Keyboard::Key::Down) ? 1.f : 0.f) -
                  (input.isKeyDown(sf::Keyboard::Key::Up) ? 1.f : 0.f);
    if (direction.x != 0.f || direction.y != 0.f)
        autopilot = false;
    else if (autopilot)
    {
        float nearest = 1e30f;
        for (const std::unique_ptr<Coin>& coin : coins)
        {
            const sf::Vector2f towards = coin->getPosition() - player->getPosition();
            const float distance = hitbox::length(hitbox::toVec2(towards));
            if (distance < nearest && distance > 0.f)
            {
                nearest = distance;
                direction = towards / distance;
            }
        }
    }
    const float length = hitbox::length(hitbox::toVec2(direction));
    player->setVelocity(length > 0.f ? direction * (playerSpeed / length) : sf::Vector2f{});
}

void WorldLevel::wander(float dt)
{
    turnClock += dt;
    if (turnClock < enemyTurnSeconds)
        return;
    turnClock -= enemyTurnSeconds;
    std::uniform_real_distribution<float> turn(-1.f, 1.f);
    for (std::unique_ptr<Enemy>& enemy : enemies)
    {
        // Turn by up to a radian either way, keeping the speed.
        const sf::Vector2f v = enemy->getVelocity();
        const float angle = turn(random);
        enemy->setVelocity({v.x * std::cos(angle) - v.y * std::sin(angle),
                            v.x * std::sin(angle) + v.y * std::cos(angle)});
    }
}

void WorldLevel::update(float dt)
{
    player->update(dt);
    wander(dt);
    for (std::unique_ptr<Enemy>& enemy : enemies)
        enemy->update(dt);
    world.checkCollisions();
    score += removeCollectedCoins(world, coins);
    if (newWaves && coins.empty())
        for (int index = 0; index < startCoins; ++index)
            addRandomCoin();
}

void WorldLevel::render(sf::RenderTarget& target) const
{
    for (const std::unique_ptr<Coin>& coin : coins)
    {
        sf::CircleShape drawn(coinRadius, 32);
        drawn.setOrigin({coinRadius, coinRadius});
        drawn.setPosition(coin->getPosition());
        drawn.setFillColor(coin->getFillColor());
        target.draw(drawn);
    }
    for (const std::unique_ptr<Enemy>& enemy : enemies)
        target.draw(*enemy);
    // A hurt player blinks: drawn in every other tenth of a second of its blink.
    if (!player->isBlinking() || std::fmod(player->getBlinkLeft(), 0.2f) < 0.1f)
        target.draw(*player);
}

void WorldLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    // What the broadphase built (grid cells, quadtree nodes or sweep bars), then every
    // object in the shape its exact test uses, hatched vermillion when it collided this step.
    hitbox::drawBroadphase(debug, world.getBroadphaseLayout());
    // The panel: why the pair under the mouse (else the last pair that met or parted) does
    // or does not collide.
    std::vector<const hitbox::GameObject*> objects{player.get()};
    for (const std::unique_ptr<Coin>& coin : coins)
        objects.push_back(coin.get());
    for (const std::unique_ptr<Enemy>& enemy : enemies)
        objects.push_back(enemy.get());
    hitbox::explainInPanel(debug, world, hitbox::toVec2(mouse), objects);
    const auto collided = [this](const hitbox::GameObject& object)
    {
        for (const auto& pair : world.getCollisions())
            if (pair.first == &object || pair.second == &object)
                return true;
        return false;
    };
    // Each object as the shape the World tests it as (its ShapeTable row's outline).
    for (const hitbox::GameObject* object : objects)
        debug.objectShape(*object, world.getShape(*object),
                          collided(*object) ? hitbox::DebugState::Overlapping
                                            : hitbox::DebugState::Free,
                          world.getShapes());
}

// The keys, then the score and what the last step's collision check cost (redrawn every
// frame): press M and watch the box tests change while the exact tests stay the same.
std::string WorldLevel::getHelpText() const
{
    char text[200];
    std::snprintf(text, sizeof text,
                  "Arrows move  A autopilot  M method  R restart  |  score %d  hurt %d  |  %s: "
                  "%zu box tests, %zu exact",
                  score, player->getHurtCount(), hitbox::toString(world.getMethod()),
                  world.getBroadphaseStats().pairsTested, world.getExactTests());
    return text;
}

std::string WorldLevel::describeState() const
{
    const hitbox::BroadphaseStats stats = world.getBroadphaseStats();
    char text[200];
    std::snprintf(text, sizeof text,
                  "score %d, hurt %d times, %d coins left, %d enemies; %s: %zu box tests, %zu "
                  "exact tests, %zu collisions",
                  score, player->getHurtCount(), getCoinCount(), getEnemyCount(),
                  hitbox::toString(world.getMethod()), stats.pairsTested, world.getExactTests(),
                  world.getCollisions().size());
    return text;
}

std::vector<hitbox::PairEvent> WorldLevel::getContactEvents() const
{
    return world.getEvents();
}

const Player& WorldLevel::getPlayer() const
{
    return *player;
}

int WorldLevel::getCoinCount() const
{
    return static_cast<int>(coins.size());
}

const Coin& WorldLevel::getCoin(int index) const
{
    return *coins.at(static_cast<std::size_t>(index));
}

int WorldLevel::getEnemyCount() const
{
    return static_cast<int>(enemies.size());
}

const Enemy& WorldLevel::getEnemy(int index) const
{
    return *enemies.at(static_cast<std::size_t>(index));
}

int WorldLevel::getScore() const
{
    return score;
}

const hitbox::World& WorldLevel::getWorld() const
{
    return world;
}
