// A geometry file that includes the object layer above it: the layer check must refuse it.
#include "hitbox/objects/GameObject.h"
