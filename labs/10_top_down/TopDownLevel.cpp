#include "TopDownLevel.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
const hitbox::Vec2 playerHitbox{30.f, 16.f};
const hitbox::Vec2 playerSprite{44.f, 66.f};
const hitbox::Vec2 enemyHitbox{34.f, 18.f};
const hitbox::Vec2 enemySprite{48.f, 40.f};
const hitbox::Vec2 trunkHitbox{22.f, 14.f};
const hitbox::Vec2 treeSprite{96.f, 150.f};
const float wallThickness = 24.f;
const float helpBarHeight = 24.f;

const sf::Color groundColor{64, 92, 58};
const sf::Color wallColor{120, 112, 100};
const sf::Color playerColor{90, 150, 235};
const sf::Color enemyColor{200, 80, 90};
const sf::Color trunkColor{110, 75, 45};
const sf::Color leavesColor{40, 120, 55};
} // namespace

TopDownLevel::TopDownLevel()
{
    buildScene();
}

void TopDownLevel::clearScene()
{
    enemies.clear();
    trees.clear();
    walls.clear();
    solids.clear();
    const sf::Vector2f world = getWorldSize();
    sight = emptySightGrid({world.x, world.y});
    const float playBottom = world.y - helpBarHeight;
    addWall({0.f, 0.f, world.x, wallThickness});
    addWall({0.f, playBottom - wallThickness, world.x, wallThickness});
    addWall({0.f, 0.f, wallThickness, playBottom});
    addWall({world.x - wallThickness, 0.f, wallThickness, playBottom});
}

void TopDownLevel::buildScene()
{
    clearScene();
    addWall({380.f, 150.f, 300.f, 40.f}); // a long wall to slide along
    addWall({640.f, 190.f, 40.f, 180.f});
    addWall({150.f, 470.f, 70.f, 60.f}); // rocks
    addWall({900.f, 430.f, 90.f, 70.f});
    addTree({300.f, 330.f});
    addTree({520.f, 470.f});
    addTree({820.f, 250.f});
    addTree({1050.f, 320.f});
    addEnemy({170.f, 292.f}); // walks behind the first tree to reach the player
    addEnemy({980.f, 560.f});
    addEnemy({1000.f, 120.f});
    // The player starts just behind (above) a tree: the leaves cover part of it.
    placePlayer({352.f, 296.f});
}

void TopDownLevel::addWall(const hitbox::Box& wall)
{
    walls.push_back(wall);
    solids.push_back(wall);
    markWall(sight, wall);
}

void TopDownLevel::addTree(hitbox::Vec2 trunkFeet)
{
    Actor tree;
    tree.feet = trunkFeet;
    tree.hitboxSize = trunkHitbox;
    tree.spriteSize = treeSprite;
    trees.push_back(tree);
    solids.push_back(tree.hitbox()); // only the trunk blocks; you walk behind the leaves
}

void TopDownLevel::addEnemy(hitbox::Vec2 feet)
{
    Enemy enemy;
    enemy.body.feet = feet;
    enemy.body.hitboxSize = enemyHitbox;
    enemy.body.spriteSize = enemySprite;
    enemy.body.health = enemyHealth;
    enemies.push_back(enemy);
}

void TopDownLevel::placePlayer(hitbox::Vec2 feet)
{
    player = Actor{};
    player.feet = feet;
    player.hitboxSize = playerHitbox;
    player.spriteSize = playerSprite;
    player.health = playerHealth;
}

void TopDownLevel::handleInput(const hitbox::Input& input, float)
{
    heldDirection = {0.f, 0.f};
    if (input.isKeyDown(sf::Keyboard::Key::A) || input.isKeyDown(sf::Keyboard::Key::Left))
        heldDirection.x -= 1.f;
    if (input.isKeyDown(sf::Keyboard::Key::D) || input.isKeyDown(sf::Keyboard::Key::Right))
        heldDirection.x += 1.f;
    if (input.isKeyDown(sf::Keyboard::Key::W) || input.isKeyDown(sf::Keyboard::Key::Up))
        heldDirection.y -= 1.f;
    if (input.isKeyDown(sf::Keyboard::Key::S) || input.isKeyDown(sf::Keyboard::Key::Down))
        heldDirection.y += 1.f;
    if (input.isPressed(sf::Keyboard::Key::Space))
        swingPressed = true;
    if (input.isPressed(sf::Keyboard::Key::R))
    {
        buildScene();
        defeats = 0;
    }
}

void TopDownLevel::moveAndSlide(Actor& actor, hitbox::Vec2 move) const
{
    // BEGIN TASK 1: move along x and resolve, then along y and resolve
    // [slide:topdown-per-axis]
    // One axis at a time, so we always know which way the actor came in: moving right
    // into a wall, its right edge goes back to the wall's left edge (as in Rodrigo
    // Monteiro, "The guide to implementing 2D platformers", tile-based movement).
    actor.feet.x += move.x;
    for (const hitbox::Box& solid : solids)
        if (hitbox::boxVsBox(actor.hitbox(), solid))
        {
            if (move.x > 0.f)
                actor.feet.x = solid.left - actor.hitboxSize.x / 2.f;
            else if (move.x < 0.f)
                actor.feet.x = solid.left + solid.width + actor.hitboxSize.x / 2.f;
        }
    // Then y. Blocked on y does not cancel the x move: walking diagonally into a wall
    // slides along it.
    actor.feet.y += move.y;
    for (const hitbox::Box& solid : solids)
        if (hitbox::boxVsBox(actor.hitbox(), solid))
        {
            if (move.y > 0.f)
                actor.feet.y = solid.top - actor.hitboxSize.y / 2.f;
            else if (move.y < 0.f)
                actor.feet.y = solid.top + solid.height + actor.hitboxSize.y / 2.f;
        }
    // [/slide]
    // STARTER TASK 1
    // actor.feet += move; // for now, straight through everything
    // END TASK 1
}

// [slide:topdown-notice-radius]
EnemyState TopDownLevel::chooseEnemyState(hitbox::Vec2 enemyFeet, hitbox::Vec2 playerFeet)
{
    // BEGIN TASK 2: attack inside the attack radius, chase inside the notice radius
    // Two circles around the enemy; the small one is checked first. pointInCircle compares
    // squared distances, no square root (and exactly on the circle is outside: the edge rule).
    if (hitbox::pointInCircle(playerFeet, {enemyFeet, attackRadius}))
        return EnemyState::Attack;
    if (hitbox::pointInCircle(playerFeet, {enemyFeet, noticeRadius}))
        return EnemyState::Chase;
    return EnemyState::Idle;
    // STARTER TASK 2
    // (void)enemyFeet;
    // (void)playerFeet;
    // return EnemyState::Idle; // for now every enemy ignores the player
    // END TASK 2
}
// [/slide]

// [slide:topdown-knockback]
bool TopDownLevel::hurt(Actor& victim, hitbox::Vec2 from, float invulnerableSeconds)
{
    // BEGIN TASK 3: knockback and invulnerability time
    // Just hit: further hits do nothing for a while. Without this, an enemy standing on
    // the player would take a life every time its attack came round again.
    if (victim.invulnerable > 0.f)
        return false; // still invulnerable: this hit does nothing
    victim.health -= 1;
    victim.knockback = directionFrom(from, victim.feet) * knockbackSpeed;
    victim.invulnerable = invulnerableSeconds;
    return true;
    // STARTER TASK 3
    // (void)from;
    // (void)invulnerableSeconds;
    // victim.health -= 1; // for now: every hit counts, and nobody is pushed away
    // return true;
    // END TASK 3
}
// [/slide]

void TopDownLevel::fadeKnockback(Actor& actor, float dt) const
{
    const float speed = std::hypot(actor.knockback.x, actor.knockback.y);
    const float slower = std::max(0.f, speed - knockbackFade * dt);
    actor.knockback = speed > 0.f ? actor.knockback * (slower / speed) : hitbox::Vec2{};
    actor.invulnerable = std::max(0.f, actor.invulnerable - dt);
}

void TopDownLevel::update(float dt)
{
    updatePlayer(dt);
    for (Enemy& enemy : enemies)
        if (enemy.body.alive)
            updateEnemy(enemy, dt);
    // Remove the defeated after the loop, never while walking the list.
    enemies.erase(std::remove_if(enemies.begin(), enemies.end(),
                                 [](const Enemy& enemy) { return !enemy.body.alive; }),
                  enemies.end());

    if (player.health <= 0)
    {
        ++defeats;
        const hitbox::Vec2 feet = player.feet;
        placePlayer(feet); // back on its feet, full health, where it fell
        player.invulnerable = playerInvulnerable;
    }
}

void TopDownLevel::updatePlayer(float dt)
{
    // Eight directions at the same speed: the diagonal is normalised, not 1.4 times faster.
    hitbox::Vec2 velocity;
    if (heldDirection.x != 0.f || heldDirection.y != 0.f)
    {
        velocity = directionFrom({0.f, 0.f}, heldDirection) * playerSpeed;
        facing = std::abs(heldDirection.x) >= std::abs(heldDirection.y)
                     ? hitbox::Vec2(heldDirection.x, 0.f)
                     : hitbox::Vec2(0.f, heldDirection.y);
    }
    // While knocked back, the hit moves the player, not the keys.
    if (player.knockback.x != 0.f || player.knockback.y != 0.f)
        velocity = player.knockback;
    moveAndSlide(player, velocity * dt);
    fadeKnockback(player, dt);

    if (swingPressed)
        swordTimeLeft = swordSeconds;
    swingPressed = false;
    if (swordTimeLeft > 0.f)
    {
        for (Enemy& enemy : enemies)
            if (enemy.body.alive && hitbox::boxVsBox(swordBox(), enemy.body.hitbox()) &&
                hurt(enemy.body, player.feet, enemyInvulnerable) && enemy.body.health <= 0)
                enemy.body.alive = false;
        swordTimeLeft = std::max(0.f, swordTimeLeft - dt);
    }
}

void TopDownLevel::updateEnemy(Enemy& enemy, float dt)
{
    Actor& body = enemy.body;
    enemy.state = chooseEnemyState(body.feet, player.feet);
    // Behind a wall the player is out of sight: the enemy stays where it is (task 4).
    if (enemy.state != EnemyState::Idle && !canSee(sight, body.feet, player.feet))
        enemy.state = EnemyState::Idle;
    enemy.attackCooldown = std::max(0.f, enemy.attackCooldown - dt);

    hitbox::Vec2 velocity;
    if (enemy.state == EnemyState::Chase)
        velocity = directionFrom(body.feet, player.feet) * enemySpeed;
    if (enemy.state == EnemyState::Attack && enemy.attackCooldown <= 0.f)
    {
        hurt(player, body.feet, playerInvulnerable);
        enemy.attackCooldown = enemyAttackInterval;
    }
    if (body.knockback.x != 0.f || body.knockback.y != 0.f)
        velocity = body.knockback;
    moveAndSlide(body, velocity * dt);
    fadeKnockback(body, dt);
}

hitbox::Box TopDownLevel::swordBox() const
{
    // A 40 x 40 box just in front of the player's feet, on the side it faces.
    const hitbox::Vec2 reach{40.f, 40.f};
    const hitbox::Vec2 center =
        player.feet + hitbox::Vec2(facing.x * (player.hitboxSize.x / 2.f + reach.x / 2.f),
                                   facing.y * (player.hitboxSize.y / 2.f + reach.y / 2.f));
    return {center.x - reach.x / 2.f, center.y - reach.y / 2.f, reach.x, reach.y};
}

// [slide:topdown-depth-sort]
std::vector<DrawItem> TopDownLevel::drawOrder() const
{
    std::vector<std::pair<float, DrawItem>> items;
    for (std::size_t index = 0; index < trees.size(); ++index)
        items.push_back({trees[index].depth(), {DrawItem::Tree, static_cast<int>(index)}});
    for (std::size_t index = 0; index < enemies.size(); ++index)
        items.push_back({enemies[index].body.depth(), {DrawItem::Enemy, static_cast<int>(index)}});
    items.push_back({player.depth(), {DrawItem::Player, 0}});
    // Back to front: smaller feet y is further away, drawn first, covered by what is nearer.
    std::stable_sort(items.begin(), items.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<DrawItem> order;
    for (const auto& item : items)
        order.push_back(item.second);
    return order;
}
// [/slide]

bool TopDownLevel::isBlinkedOut(const Actor& actor)
{
    return actor.invulnerable > 0.f && static_cast<int>(actor.invulnerable * 20.f) % 2 == 1;
}

namespace
{
void drawBox(sf::RenderTarget& target, const hitbox::Box& box, sf::Color color)
{
    sf::RectangleShape shape({box.width, box.height});
    shape.setPosition({box.left, box.top});
    shape.setFillColor(color);
    target.draw(shape);
}

sf::Color faded(sf::Color color, bool fade)
{
    if (fade)
        color.a = 70;
    return color;
}

void drawTree(sf::RenderTarget& target, const Actor& tree)
{
    const hitbox::Box sprite = tree.spriteBox();
    const hitbox::Box trunk{tree.feet.x - 12.f, sprite.top + sprite.height - 60.f, 24.f, 60.f};
    drawBox(target, trunk, trunkColor);
    sf::CircleShape leaves(sprite.width / 2.f);
    leaves.setPosition({sprite.left, sprite.top});
    leaves.setScale({1.f, 1.1f});
    leaves.setFillColor(leavesColor);
    leaves.setOutlineThickness(-3.f);
    leaves.setOutlineColor(sf::Color(30, 90, 40));
    target.draw(leaves);
}

void drawPerson(sf::RenderTarget& target, const Actor& actor)
{
    const hitbox::Box sprite = actor.spriteBox();
    const bool fade = TopDownLevel::isBlinkedOut(actor);
    drawBox(target,
            {sprite.left + 6.f, sprite.top + 22.f, sprite.width - 12.f, sprite.height - 22.f},
            faded(playerColor, fade));
    sf::CircleShape head(14.f);
    head.setPosition({actor.feet.x - 14.f, sprite.top});
    head.setFillColor(faded(sf::Color(245, 205, 170), fade));
    target.draw(head);
}

void drawSlime(sf::RenderTarget& target, const Enemy& enemy)
{
    const hitbox::Box sprite = enemy.body.spriteBox();
    const bool fade = TopDownLevel::isBlinkedOut(enemy.body);
    sf::CircleShape blob(sprite.width / 2.f);
    blob.setScale({1.f, sprite.height / sprite.width});
    blob.setPosition({sprite.left, sprite.top});
    sf::Color color = enemy.state == EnemyState::Idle ? sf::Color(150, 90, 120) : enemyColor;
    blob.setFillColor(faded(color, fade));
    target.draw(blob);
    for (float side : {-9.f, 5.f})
        drawBox(target, {enemy.body.feet.x + side, sprite.top + 12.f, 4.f, 7.f},
                faded(sf::Color(30, 20, 20), fade));
}
} // namespace

void TopDownLevel::render(sf::RenderTarget& target) const
{
    drawBox(target, {0.f, 0.f, getWorldSize().x, getWorldSize().y}, groundColor);
    for (const hitbox::Box& wall : walls)
        drawBox(target, wall, wallColor);

    for (const DrawItem& item : drawOrder())
    {
        if (item.kind == DrawItem::Tree)
            drawTree(target, trees[static_cast<std::size_t>(item.index)]);
        else if (item.kind == DrawItem::Enemy)
            drawSlime(target, enemies[static_cast<std::size_t>(item.index)]);
        else
            drawPerson(target, player);
    }
    if (isSwinging())
        drawBox(target, swordBox(), sf::Color(230, 230, 240, 150));

    std::ostringstream hud;
    hud << "health " << player.health << "/" << playerHealth;
    if (player.invulnerable > 0.f)
        hud << "   invulnerable " << std::round(player.invulnerable * 10.f) / 10.f << " s";
    hud << "   enemies " << enemies.size() << "   defeats " << defeats;
    sf::Text text = hitbox::makeText(font.get(), hud.str(), 18);
    text.setPosition({36.f, 28.f});
    text.setFillColor(sf::Color::White);
    target.draw(text);
}

void TopDownLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    using hitbox::DebugRenderer;
    for (const hitbox::Box& solid : solids)
        debug.box(solid, DebugRenderer::freeColor);
    for (const Actor& tree : trees)
        debug.box(tree.spriteBox(), DebugRenderer::hintColor);
    for (const Enemy& enemy : enemies)
    {
        const Actor& body = enemy.body;
        debug.box(body.spriteBox(), DebugRenderer::hintColor);
        debug.box(body.hitbox(), body.invulnerable > 0.f ? DebugRenderer::overlappingColor
                                                         : DebugRenderer::freeColor);
        debug.circle({body.feet, noticeRadius}, enemy.state == EnemyState::Idle
                                                    ? DebugRenderer::hintColor
                                                    : DebugRenderer::velocityColor);
        debug.circle({body.feet, attackRadius}, enemy.state == EnemyState::Attack
                                                    ? DebugRenderer::overlappingColor
                                                    : DebugRenderer::hintColor);
        if (enemy.state != EnemyState::Idle)
            debug.line(body.feet, player.feet, DebugRenderer::velocityColor);
        if (body.knockback.x != 0.f || body.knockback.y != 0.f)
            debug.arrow(body.feet, body.feet + body.knockback * 0.1f, DebugRenderer::normalColor);
    }
    debug.box(player.spriteBox(), DebugRenderer::hintColor);
    debug.box(player.hitbox(), player.invulnerable > 0.f ? DebugRenderer::overlappingColor
                                                         : DebugRenderer::freeColor);
    if (player.knockback.x != 0.f || player.knockback.y != 0.f)
        debug.arrow(player.feet, player.feet + player.knockback * 0.1f, DebugRenderer::normalColor);
    if (isSwinging())
        debug.box(swordBox(), DebugRenderer::overlappingColor);
}

std::string TopDownLevel::getHelpText() const
{
    return "WASD/arrows walk  Space sword  R restart";
}

std::string TopDownLevel::describeState() const
{
    std::ostringstream out;
    out << "player at (" << player.feet.x << ", " << player.feet.y << ") health " << player.health
        << ", " << enemies.size() << " enemies, defeats " << defeats;
    return out.str();
}
