// A geometry file that includes only geometry: the layer check lets it through.
#include "hitbox/geometry/Vec2.h"
