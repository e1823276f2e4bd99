// CommandLine.h - parses a command line as a program's main() would get it: "program"
// followed by `arguments`, for a program named "Test" with `extraOptions` of its own.
#pragma once

#include "hitbox/app/Options.h"

#include <string>
#include <vector>

inline hitbox::Options parseCommandLine(std::vector<const char*> arguments,
                                        const std::vector<std::string>& extraOptions = {})
{
    arguments.insert(arguments.begin(), "program");
    return hitbox::parseOptions(static_cast<int>(arguments.size()), arguments.data(),
                                {"Test", extraOptions});
}
