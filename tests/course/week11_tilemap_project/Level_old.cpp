// An old copy the student kept while rewriting the level. The Visual Studio project does not
// compile it (it is not in the ClCompile list), and neither must Hitbox: it defines the same
// functions as level.cpp and includes a header that no longer exists.
#include "OldLevel.h"

Level::Level(sf::RenderWindow* hwnd, Input* in)
{
	window = hwnd;
	input = in;
}
