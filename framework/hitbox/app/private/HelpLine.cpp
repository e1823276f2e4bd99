#include "hitbox/app/private/HelpLine.h"

#include "hitbox/app/Keys.h"
#include "hitbox/debug/DebugRenderer.h"

namespace hitbox
{

std::string helpLine(const Level& level, bool showDebug, int framesPerSecond)
{
    std::string line = showDebug ? std::string(DebugRenderer::legend) + "   |   " : "";
    line += sharedKeysHelp();
    const std::string levelKeys = level.getHelpText();
    if (!levelKeys.empty())
        line += "   |   " + levelKeys;
    if (framesPerSecond > 0)
        line += "   |   " + std::to_string(framesPerSecond) + " fps";
    return line;
}

} // namespace hitbox
