// LevelSnapshot.cpp - lab 8's state as a value, so the window can rewind it (hitbox::RewindLevel,
// framework/hitbox/app/Rewind.h): Left/Right while paused show the last 10 seconds again.
// What is not here is rebuilt (the broadphase, this step's items and pairs) or only measured
// (timings), and no step reads it before writing it: ManyObjectsState in ManyObjectsLevel.h.
#include "ManyObjectsLevel.h"

#include <memory>

namespace
{

struct Snapshot : hitbox::LevelState
{
    explicit Snapshot(const ManyObjectsState& saved) : state(saved) {}

    std::size_t bytes() const override
    {
        return sizeof(Snapshot) + state.balls.capacity() * sizeof(Ball);
    }

    ManyObjectsState state;
};

} // namespace

std::unique_ptr<hitbox::LevelState> ManyObjectsLevel::saveState() const
{
    return std::make_unique<Snapshot>(static_cast<const ManyObjectsState&>(*this));
}

void ManyObjectsLevel::restoreState(const hitbox::LevelState& state)
{
    static_cast<ManyObjectsState&>(*this) = static_cast<const Snapshot&>(state).state;
    rebuildBroadphase();
    warmUpBroadphase();
}
