// LevelSnapshot.cpp - lab 8's state as a value, so the window can rewind it (hitbox::RewindLevel,
// framework/hitbox/app/Rewind.h): Left/Right while paused show the last 10 seconds again.
// What is not here is rebuilt (the broadphase, this step's items and pairs) or only measured
// (timings), and no step reads it before writing it.
#include "ManyObjectsLevel.h"

namespace
{

struct Snapshot : hitbox::LevelState
{
    Scene scene = Scene::Crowd;
    hitbox::BroadphaseMethod method = hitbox::BroadphaseMethod::Grid;
    std::mt19937 random;
    std::vector<Ball> balls;
    PairTable table;
    std::size_t contacts = 0;
    bool bruteForceSkipped = false;
    std::size_t ownShipHits = 0;
    std::size_t pickupBumps = 0;
    float gridCellScale = 1.f;
    float fireTimer = 0.f;
    float fireAngle = 0.f;
    float secondsSincePrint = 0.f;

    std::size_t bytes() const override
    {
        return sizeof(Snapshot) + balls.capacity() * sizeof(Ball);
    }
};

} // namespace

std::unique_ptr<hitbox::LevelState> ManyObjectsLevel::saveState() const
{
    auto saved = std::make_unique<Snapshot>();
    saved->scene = scene;
    saved->method = method;
    saved->random = random;
    saved->balls = balls;
    saved->table = table;
    saved->contacts = contacts;
    saved->bruteForceSkipped = bruteForceSkipped;
    saved->ownShipHits = ownShipHits;
    saved->pickupBumps = pickupBumps;
    saved->gridCellScale = gridCellScale;
    saved->fireTimer = fireTimer;
    saved->fireAngle = fireAngle;
    saved->secondsSincePrint = secondsSincePrint;
    return saved;
}

void ManyObjectsLevel::restoreState(const hitbox::LevelState& state)
{
    const Snapshot& saved = static_cast<const Snapshot&>(state);
    scene = saved.scene;
    method = saved.method;
    random = saved.random;
    balls = saved.balls;
    table = saved.table;
    contacts = saved.contacts;
    bruteForceSkipped = saved.bruteForceSkipped;
    ownShipHits = saved.ownShipHits;
    pickupBumps = saved.pickupBumps;
    gridCellScale = saved.gridCellScale;
    fireTimer = saved.fireTimer;
    fireAngle = saved.fireAngle;
    secondsSincePrint = saved.secondsSincePrint;
    rebuildBroadphase();
    warmUpBroadphase();
}
