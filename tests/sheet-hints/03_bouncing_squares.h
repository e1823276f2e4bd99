// Lab 3's hints are written inside Square's functions (Square.cpp).
#pragma once
#include "Square.h"

struct HintScope : Square
{
    void hints();
};
