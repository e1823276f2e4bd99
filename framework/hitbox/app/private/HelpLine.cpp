#include "hitbox/app/private/HelpLine.h"

#include "hitbox/app/Keys.h"
#include "hitbox/debug/DebugRenderer.h"

namespace hitbox
{

std::string helpLine(const Level& level, bool showDebug, int framesPerSecond)
{
    std::string line = showDebug ? std::string(DebugRenderer::legend) + "   |   " : "";
    // The level's own text before the shared keys: it holds the score and the lab's keys, and
    // the shared keys are the same in every window (docs/programs.md) when a long line is cut.
    const std::string levelKeys = level.getHelpText();
    if (!levelKeys.empty())
        line += levelKeys + "   |   ";
    line += sharedKeysHelp();
    if (framesPerSecond > 0)
        line += "   |   " + std::to_string(framesPerSecond) + " fps";
    return line;
}

} // namespace hitbox
