#include "hitbox/objects/ContactEvent.h"

namespace hitbox
{

const char* toString(ContactPhase phase)
{
    switch (phase)
    {
    case ContactPhase::Enter:
        return "enter";
    case ContactPhase::Stay:
        return "stay";
    case ContactPhase::Exit:
        return "exit";
    }
    return "?";
}

} // namespace hitbox
