// Fuzz target: the shared command line and the typed getters fed any arguments.
// The input is split at zero bytes into argv. parseOptions and every getter either answer
// (within the stated range) or throw std::invalid_argument with ONE printable line; a
// crash, a sanitizer report (signed overflow included) or anything else is a bug, and its
// input is kept in corpus/options/ as a regression test.
#include "hitbox/app/Options.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
void requireOnePrintableLine(const std::string& message)
{
    for (const char c : message)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
            std::abort();
}

// Runs `read`; a bad value may only ever throw std::invalid_argument with a clean line.
template <typename Read>
void answersOrRefuses(Read read)
{
    try
    {
        read();
    }
    catch (const std::invalid_argument& error)
    {
        requireOnePrintableLine(error.what());
    }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::vector<std::string> words(1, "program");
    words.emplace_back();
    for (std::size_t i = 0; i < size; ++i)
    {
        if (data[i] == 0)
            words.emplace_back();
        else
            words.back() += static_cast<char>(data[i]);
    }
    std::vector<const char*> argv;
    for (const std::string& word : words)
        argv.push_back(word.c_str());

    const hitbox::ProgramInfo info{"Fuzz", {"--count", "--speed", "--demo", "--mode"}};
    answersOrRefuses(
        [&]
        {
            const hitbox::Options options =
                hitbox::parseOptions(static_cast<int>(argv.size()), argv.data(), info);
            if (options.frames < -1 || options.frames > hitbox::maxSteps)
                std::abort();
            answersOrRefuses(
                [&]
                {
                    const long long count = options.wholeNumber("--count", 2, -10, 1000);
                    if (count < -10 || count > 1000)
                        std::abort();
                });
            answersOrRefuses(
                [&]
                {
                    const double speed = options.number("--speed", 1.0, 0.0, 1e6);
                    if (!(speed >= 0.0 && speed <= 1e6))
                        std::abort();
                });
            answersOrRefuses(
                [&] { [[maybe_unused]] const bool demo = options.onOff("--demo", false); });
            answersOrRefuses(
                [&]
                {
                    const std::string mode = options.oneOf("--mode", "a", {"a", "b"});
                    if (mode != "a" && mode != "b")
                        std::abort();
                });
        });
    return 0;
}
