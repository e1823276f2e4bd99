// A geometry file that includes SFML: the layer check must refuse it (geometry knows no SFML).
#include <SFML/Graphics/Rect.hpp>
