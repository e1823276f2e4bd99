// TopDownLevel.h - Lab 10: a Zelda-like scene seen from above.
//
// The player walks among walls, rocks, trees and a few slimes. The ideas, each
// somewhere you can find it:
//   - a hitbox smaller than the sprite: only the feet collide (Actor.h);
//   - per-axis move-then-resolve: move along x, push out of walls along x; then the same
//     along y. Walking diagonally into a wall slides along it (moveAndSlide);
//   - enemies with a notice radius (start chasing) and an attack radius (hit), tested as
//     "is the player's feet point inside this circle?" (chooseEnemyState), and only when
//     no wall stands between them (canSee, LineOfSight.h: a grid ray cast);
//   - a hit knocks the victim back and makes it invulnerable for a while, blinking (hurt);
//   - depth sorting: actors are drawn in order of their feet's y, so the one further down
//     the screen covers the one behind it (drawOrder).
#pragma once

#include "Actor.h"
#include "LineOfSight.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"

#include <string>
#include <vector>

enum class EnemyState
{
    Idle,   // the player is out of sight: stay
    Chase,  // inside the notice radius: walk towards the player
    Attack, // inside the attack radius: stop and strike
};

struct Enemy
{
    Actor body;
    EnemyState state = EnemyState::Idle;
    float attackCooldown = 0.f; // seconds until it can strike again
};

// Something to draw, in the order drawOrder() returns.
struct DrawItem
{
    enum Kind
    {
        Tree,
        Enemy,
        Player
    } kind;
    int index; // into getTrees() / getEnemies(); 0 for the player
};

class TopDownLevel : public hitbox::Level
{
public:
    // Tuning, in pixels and seconds.
    static constexpr float playerSpeed = 240.f;
    static constexpr float enemySpeed = 130.f;
    static constexpr float noticeRadius = 260.f;
    static constexpr float attackRadius = 56.f;
    static constexpr float enemyAttackInterval = 0.8f;
    static constexpr float knockbackSpeed = 700.f;    // px/s just after a hit
    static constexpr float knockbackFade = 3500.f;    // px/s^2: gone after 0.2 s, 70 px
    static constexpr float playerInvulnerable = 1.0f; // s after the player is hit
    static constexpr float enemyInvulnerable = 0.4f;  // s after an enemy is hit
    static constexpr float swordSeconds = 0.15f;      // how long a swing can hit
    static constexpr int playerHealth = 5;
    static constexpr int enemyHealth = 3;

    TopDownLevel();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // What an enemy at `enemyFeet` does about a player at `playerFeet` (circle tests).
    static EnemyState chooseEnemyState(hitbox::Vec2 enemyFeet, hitbox::Vec2 playerFeet);
    // A hit on `victim` from something at `from`. Returns false when the hit did nothing
    // (the victim was still invulnerable).
    static bool hurt(Actor& victim, hitbox::Vec2 from, float invulnerableSeconds);
    // Moves an actor by `move` pixels, stopping it at every wall and tree trunk.
    void moveAndSlide(Actor& actor, hitbox::Vec2 move) const;
    // Everything that walks or stands, back to front: sorted by Actor::depth().
    std::vector<DrawItem> drawOrder() const;
    // Drawn faded this frame? (blinking while invulnerable: 10 blinks a second)
    static bool isBlinkedOut(const Actor& actor);

    // For tests: empty the scene but for its outer walls, then add things.
    void clearScene();
    void addWall(const hitbox::Box& wall);
    void addTree(hitbox::Vec2 trunkFeet);
    void addEnemy(hitbox::Vec2 feet);
    void placePlayer(hitbox::Vec2 feet);

    const Actor& getPlayer() const { return player; }
    const std::vector<Enemy>& getEnemies() const { return enemies; }
    const std::vector<Actor>& getTrees() const { return trees; }
    const std::vector<hitbox::Box>& getWalls() const { return walls; }
    const hitbox::TileGrid& getSight() const { return sight; } // the walls as canSee's tiles
    bool isSwinging() const { return swordTimeLeft > 0.f; }
    hitbox::Box swordBox() const;
    int getDefeats() const { return defeats; }

private:
    void updatePlayer(float dt);
    void updateEnemy(Enemy& enemy, float dt);
    void fadeKnockback(Actor& actor, float dt) const;
    void buildScene();

    Actor player;
    std::vector<Enemy> enemies;
    std::vector<Actor> trees;
    std::vector<hitbox::Box> walls;  // walls and rocks
    hitbox::TileGrid sight;          // the walls as tiles: what blocks an enemy's sight
    std::vector<hitbox::Box> solids; // walls and tree trunks: what blocks feet
    hitbox::LazyFont font;           // read by the first render(): tests need no font file

    hitbox::Vec2 heldDirection; // from the keys, each axis -1, 0 or 1
    hitbox::Vec2 facing{0.f, 1.f};
    bool swingPressed = false;
    float swordTimeLeft = 0.f;
    int defeats = 0;
};
