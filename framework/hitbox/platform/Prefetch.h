// Prefetch.h - asks the processor to bring memory into its cache now, because the program will
// read it soon (Ericson, Real-Time Collision Detection, 13.6 "Prefetching and Preloading").
//
// Why: a read the cache does not hold waits for main memory, about 110 ns on the machine the
// labs were measured on, as long as a hundred cheap calculations. A loop that reads scattered
// objects (a pair list's balls, a grid cell's boxes) waits like that at almost every step, and
// the processor can only look a few steps ahead by itself. Asking for the objects a dozen steps
// early lets their waits overlap the work in between.
//
// A hint, never a read: nothing the program computes changes, and where the compiler has no way
// to say it the call does nothing. Knows no SFML.

#pragma once

#include <cstddef>

#if !defined(__GNUC__) && !defined(__clang__) && (defined(_M_X64) || defined(_M_IX86))
#include <xmmintrin.h>
#define HITBOX_PREFETCH_SSE 1 // MSVC on x86: _mm_prefetch
#endif

namespace hitbox::platform
{

// Asks for the cache line holding `address` (64 bytes on x86, 128 on Apple's M chips).
inline void prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
    // Kept calls: an empty asm statement the compiler must keep (it emits no instruction).
    // Without it g++ 12 at -O3 judged a function that does nothing but prefetch to have no
    // effect, and dropped every call to it (seen in the disassembly).
    __asm__ __volatile__("" : : "r"(address));
#elif defined(HITBOX_PREFETCH_SSE)
    _mm_prefetch(static_cast<const char*>(address), _MM_HINT_T0);
#else
    (void)address; // no way to ask: the read will simply wait
#endif
}

// Asks for the lines of a small object, which can lie across two of them: the line of its first
// byte and the line of its last.
template <typename Object>
void prefetchObject(const Object& object)
{
    static_assert(sizeof(Object) <= 64, "more than two cache lines: prefetch each line");
    const char* first = reinterpret_cast<const char*>(&object);
    prefetch(first);
    prefetch(first + sizeof(Object) - 1);
}

} // namespace hitbox::platform
