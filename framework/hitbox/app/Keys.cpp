#include "hitbox/app/Keys.h"

namespace hitbox
{

const SharedKey* findSharedKey(int key)
{
    for (const SharedKey& shared : sharedKeys)
        if (static_cast<int>(shared.key) == key)
            return &shared;
    return nullptr;
}

bool isSharedKey(int key)
{
    return findSharedKey(key) != nullptr;
}

std::string sharedKeysHelp()
{
    std::string help;
    for (const SharedKey& shared : sharedKeys)
        help += (help.empty() ? "" : "   ") + std::string(shared.help);
    return help;
}

} // namespace hitbox
