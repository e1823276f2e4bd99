// Platform.cpp - the two spellings (Windows; Linux and macOS) of every call in Platform.h.
// Nothing else in Hitbox includes a system header or calls a deprecated C runtime function.
#include "hitbox/platform/Platform.h"

#include <cstddef>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#if defined(_WIN32)
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <process.h>
#include <windows.h>
#else
#include <climits>
#include <csignal>
#include <dlfcn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h> // clock_gettime, CLOCK_THREAD_CPUTIME_ID
#include <unistd.h>
#endif

namespace hitbox::platform
{
namespace
{
// POSIX refuses such names (EINVAL); Microsoft's runtime would read "A=B" as A set to "B=...".
bool validVariableName(const std::string& name)
{
    return !name.empty() && name.find('=') == std::string::npos;
}
} // namespace

#if defined(_WIN32)

// The process's environment through the Win32 calls rather than the C runtime's getenv
// (deprecated: C4996) or _dupenv_s (missing from the msvcrt.dll that mingw-w64 links).
std::optional<std::string> environmentVariable(const std::string& name)
{
    if (!validVariableName(name))
        return std::nullopt;
    const DWORD size = GetEnvironmentVariableA(name.c_str(), nullptr, 0);
    if (size == 0)
        return GetLastError() == ERROR_ENVVAR_NOT_FOUND ? std::nullopt
                                                        : std::optional<std::string>("");
    std::string value(size, '\0');
    const DWORD length = GetEnvironmentVariableA(name.c_str(), value.data(), size);
    value.resize(length);
    return value;
}

bool setEnvironmentVariable(const std::string& name, const std::string& value)
{
    return validVariableName(name) && SetEnvironmentVariableA(name.c_str(), value.c_str()) != 0;
}

bool unsetEnvironmentVariable(const std::string& name)
{
    return validVariableName(name) && SetEnvironmentVariableA(name.c_str(), nullptr) != 0;
}

std::tm localTime(std::time_t when)
{
    std::tm local{};
    localtime_s(&local, &when);
    return local;
}

long processId()
{
    return static_cast<long>(_getpid());
}

std::string programFolder()
{
    wchar_t path[MAX_PATH] = {};
    const DWORD length = GetModuleFileNameW(nullptr, path, MAX_PATH);
    if (length == 0 || length == MAX_PATH)
        return ".";
    return std::filesystem::path(path).parent_path().string();
}

std::shared_ptr<void> loadLibrary(const std::string&)
{
    return nullptr;
}

bool makeNamedPipe(const std::string&)
{
    return false;
}

bool runWithFileSizeLimit(std::uintmax_t, const std::function<void()>&)
{
    return false;
}

std::string takeInheritedPipe(const std::string&)
{
    return "";
}

#else

std::optional<std::string> environmentVariable(const std::string& name)
{
    if (const char* value = std::getenv(name.c_str()))
        return std::string(value);
    return std::nullopt;
}

bool setEnvironmentVariable(const std::string& name, const std::string& value)
{
    return validVariableName(name) && setenv(name.c_str(), value.c_str(), 1) == 0;
}

bool unsetEnvironmentVariable(const std::string& name)
{
    return validVariableName(name) && unsetenv(name.c_str()) == 0;
}

std::tm localTime(std::time_t when)
{
    std::tm local{};
    localtime_r(&when, &local);
    return local;
}

long processId()
{
    return static_cast<long>(getpid());
}

std::string programFolder()
{
#if defined(__linux__)
    char buffer[PATH_MAX] = {};
    const ssize_t length = readlink("/proc/self/exe", buffer, sizeof(buffer) - 1);
    if (length > 0)
        return std::filesystem::path(std::string(buffer, static_cast<std::size_t>(length)))
            .parent_path()
            .string();
#endif
    return ".";
}

std::shared_ptr<void> loadLibrary(const std::string& name)
{
#if defined(__APPLE__)
    (void)name;
    return nullptr;
#else
    void* library = dlopen(name.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (library == nullptr)
        return nullptr;
    return std::shared_ptr<void>(library, [](void* loaded) { dlclose(loaded); });
#endif
}

bool makeNamedPipe(const std::string& path)
{
    return mkfifo(path.c_str(), 0600) == 0;
}

bool runWithFileSizeLimit(std::uintmax_t bytes, const std::function<void()>& work)
{
    // With SIGXFSZ ignored, a write past the limit fails with EFBIG instead of ending the
    // process: what a program sees on a disk with `bytes` free.
    rlimit previous{};
    if (getrlimit(RLIMIT_FSIZE, &previous) != 0)
        return false;
    rlimit small = previous;
    small.rlim_cur = static_cast<rlim_t>(bytes);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    if (setrlimit(RLIMIT_FSIZE, &small) != 0)
    {
        std::signal(SIGXFSZ, previousHandler);
        return false;
    }
    work();
    setrlimit(RLIMIT_FSIZE, &previous);
    std::signal(SIGXFSZ, previousHandler);
    return true;
}

std::string takeInheritedPipe(const std::string& variable)
{
    const std::optional<std::string> number = environmentVariable(variable);
    if (!number || number->empty() || number->size() > 4 ||
        number->find_first_not_of("0123456789") != std::string::npos)
        return "";
    const int descriptor = std::atoi(number->c_str());
    if (descriptor < 3) // never standard input, output or error
        return "";
    std::string text;
    char buffer[256];
    for (;;)
    {
        const ssize_t got = read(descriptor, buffer, sizeof buffer);
        if (got <= 0 || text.size() > 4096)
            break;
        text.append(buffer, static_cast<std::size_t>(got));
    }
    close(descriptor);
    return text;
}

#endif

void* findSymbol(const std::shared_ptr<void>& library, const std::string& symbol)
{
#if defined(_WIN32) || defined(__APPLE__)
    (void)library;
    (void)symbol;
    return nullptr;
#else
    return library == nullptr ? nullptr : dlsym(library.get(), symbol.c_str());
#endif
}

double threadCpuSeconds()
{
#if defined(_WIN32)
    FILETIME created, exited, kernel, user;
    if (GetThreadTimes(GetCurrentThread(), &created, &exited, &kernel, &user))
    {
        // FILETIME counts 100-nanosecond units in two 32-bit halves.
        auto ticks = [](const FILETIME& time) {
            return (static_cast<unsigned long long>(time.dwHighDateTime) << 32) |
                   time.dwLowDateTime;
        };
        return static_cast<double>(ticks(kernel) + ticks(user)) * 1e-7;
    }
#elif defined(CLOCK_THREAD_CPUTIME_ID)
    timespec now{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now) == 0)
        return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
#endif
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

bool threadCpuTimeIsPerThread()
{
#if defined(_WIN32) || defined(CLOCK_THREAD_CPUTIME_ID)
    return true;
#else
    return false;
#endif
}

} // namespace hitbox::platform
