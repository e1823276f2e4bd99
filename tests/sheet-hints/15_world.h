// Lab 15's hints are written inside Rules.cpp.
#pragma once
#include "Pieces.h"
#include "Rules.h"

struct HintScope
{
    void hints();
    Layers a, b;
};
