#include "Rules.h"

#include <algorithm>

// BEGIN TASK 1: each object on its layer, with the right mask
Layers layersFor(Kind kind)
{
    // The mask lists who this kind wants to meet; a pair is tested only when both want it.
    switch (kind)
    {
    case Kind::Player:
        return {layer::player, layer::coin | layer::enemy};
    case Kind::Coin: // only the player picks coins up
        return {layer::coin, layer::player};
    case Kind::Enemy: // enemies hurt the player and bump each other; they ignore coins
        return {layer::enemy, layer::player | layer::enemy};
    }
    return {};
}
// STARTER TASK 1
// Layers layersFor(Kind)
// {
//     return {}; // layer 1, mask "everything": every object is tested against every other
// }
// END TASK 1

// BEGIN TASK 2: collect a coin the player touches
void Coin::collisionResponse(hitbox::GameObject* other)
{
    if (other == nullptr || kindOf(*other) != Kind::Player)
        return;
    collected = true;
    // Dead objects are skipped by the World: the coin cannot be collected twice in one check.
    setAlive(false);
}

int removeCollectedCoins(hitbox::World& world, std::vector<std::unique_ptr<Coin>>& coins)
{
    int removed = 0;
    for (const std::unique_ptr<Coin>& coin : coins)
    {
        // The World keeps only a pointer to the coin, not the coin: take the pointer out
        // first, or its next checkCollisions() reads an object that no longer exists.
        if (coin->isCollected())
        {
            world.remove(*coin);
            ++removed;
        }
    }
    coins.erase(std::remove_if(coins.begin(), coins.end(),
                               [](const std::unique_ptr<Coin>& coin)
                               { return coin->isCollected(); }),
                coins.end());
    return removed;
}
// STARTER TASK 2
// void Coin::collisionResponse(hitbox::GameObject*) {}
//
// int removeCollectedCoins(hitbox::World&, std::vector<std::unique_ptr<Coin>>&)
// {
//     return 0;
// }
// END TASK 2

// BEGIN TASK 3: a blinking player is not tested against enemies
bool mayMeetNow(const hitbox::GameObject& first, const hitbox::GameObject& second)
{
    // A hurt player blinks and cannot be hurt again until it stops: skip the pair before
    // its exact test, rather than test it and then ignore the hit.
    const auto blinkingPlayer = [](const hitbox::GameObject& object)
    { return kindOf(object) == Kind::Player && static_cast<const Player&>(object).isBlinking(); };
    const bool playerAndEnemy = (blinkingPlayer(first) && kindOf(second) == Kind::Enemy) ||
                                (blinkingPlayer(second) && kindOf(first) == Kind::Enemy);
    return !playerAndEnemy;
}
// STARTER TASK 3
// bool mayMeetNow(const hitbox::GameObject&, const hitbox::GameObject&)
// {
//     return true; // no rule yet: every pair the layers allow is tested
// }
// END TASK 3
