// Lab 8's hints are written inside PairTable.cpp (task 1) and Rules.cpp (task 3).
#pragma once
#include "Rules.h"

#include <cstddef>
#include <cstdint>

struct HintScope
{
    void hints();
    std::size_t first, second; // task 1: the two indices of a pair
    std::uint32_t everything;  // task 3: every layer's bit
};
