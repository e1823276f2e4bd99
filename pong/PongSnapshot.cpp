// PongSnapshot.cpp - Pong's state as a value, so the paused window can step back through the
// last 10 seconds (hitbox::RewindLevel, framework/hitbox/app/Rewind.h); and its paddle hits as
// contact events for the rewind strip. Not saved: the font and the sounds (nothing a rule reads).
#include "PongLevel.h"

#include <memory>

namespace
{

struct Snapshot : hitbox::LevelState
{
    explicit Snapshot(const PongState& saved) : state(saved) {}

    std::size_t bytes() const override
    {
        return sizeof(Snapshot) + state.events.capacity() * sizeof(GameEvent);
    }

    PongState state;
};

} // namespace

std::unique_ptr<hitbox::LevelState> PongLevel::saveState() const
{
    return std::make_unique<Snapshot>(static_cast<const PongState&>(*this));
}

void PongLevel::restoreState(const hitbox::LevelState& state)
{
    static_cast<PongState&>(*this) = static_cast<const Snapshot&>(state).state;
}

std::vector<hitbox::PairEvent> PongLevel::getContactEvents() const
{
    std::vector<hitbox::PairEvent> contacts;
    for (GameEvent event : events)
    {
        if (event != GameEvent::PaddleHit)
            continue;
        // The paddle on the ball's side of the net is the one it bounced off.
        const Paddle& paddle = ball.getPosition().x < arena.centerX() ? leftPaddle : rightPaddle;
        for (hitbox::ContactPhase phase : {hitbox::ContactPhase::Enter, hitbox::ContactPhase::Exit})
        {
            hitbox::PairEvent contact;
            contact.phase = phase;
            contact.first = const_cast<Ball*>(&ball);
            contact.second = const_cast<Paddle*>(&paddle);
            contact.contact = lastHit.hit
                                  ? hitbox::Contact{true, lastHit.normal, 0.f, lastHit.point}
                                  : hitbox::Contact{};
            contact.step = static_cast<std::uint64_t>(stepCount);
            contacts.push_back(contact);
        }
    }
    return contacts;
}
