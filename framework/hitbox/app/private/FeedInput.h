// FeedInput.h - a window event, as the level's Input sees it.
#pragma once

#include "hitbox/app/Input.h"
#include "hitbox/sfml/Events.h"

namespace hitbox
{

// Keys and mouse buttons down and up, the wheel, and every key let go when the window loses
// the focus (so a key held while switching away does not stay down). Other events: nothing.
void feedInput(Input& input, const WindowEvent& event);

} // namespace hitbox
