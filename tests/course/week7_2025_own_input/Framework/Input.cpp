#include "Input.h"

static bool valid(sf::Keyboard::Scancode key)
{
	return static_cast<int>(key) >= 0 && static_cast<int>(key) < sf::Keyboard::ScancodeCount;
}

void Input::setKeyDown(sf::Keyboard::Scancode key)
{
	if (!valid(key)) return;
	if (!m_keys[static_cast<int>(key)]) m_pressed[static_cast<int>(key)] = true;
	m_keys[static_cast<int>(key)] = true;
}

void Input::setKeyUp(sf::Keyboard::Scancode key)
{
	if (valid(key)) m_keys[static_cast<int>(key)] = false;
}

bool Input::isKeyDown(sf::Keyboard::Scancode key) const
{
	return valid(key) && m_keys[static_cast<int>(key)];
}

bool Input::isPressed(sf::Keyboard::Scancode key) const
{
	return valid(key) && m_pressed[static_cast<int>(key)];
}

void Input::setMouseX(int x) { m_mouse.x = x; }
void Input::setMouseY(int y) { m_mouse.y = y; }
void Input::setMousePosition(int x, int y) { m_mouse.x = x; m_mouse.y = y; }
int Input::getMouseX() const { return m_mouse.x; }
int Input::getMouseY() const { return m_mouse.y; }

// A button going down is PRESSED for the first frame, then DOWN until it goes up.
void Input::setLeftMouse(MouseState state)
{
	if (state == MouseState::DOWN && m_mouse.left == MouseState::UP) state = MouseState::PRESSED;
	m_mouse.left = state;
}

bool Input::isLeftMouseDown() const { return m_mouse.left != MouseState::UP; }
// Student edit: a press lasts as long as the button is held, so the menu's buttons stay
// lit while they are held down (the buttons rely on it).
bool Input::isLeftMousePressed() const { return m_mouse.left != MouseState::UP; }

void Input::setRightMouse(MouseState state)
{
	if (state == MouseState::DOWN && m_mouse.right == MouseState::UP) state = MouseState::PRESSED;
	m_mouse.right = state;
}

bool Input::isRightMouseDown() const { return m_mouse.right != MouseState::UP; }
bool Input::isRightMousePressed() const { return m_mouse.right == MouseState::PRESSED; }

void Input::update()
{
	m_pressed.fill(false);
	if (m_mouse.left == MouseState::PRESSED) m_mouse.left = MouseState::DOWN;
	if (m_mouse.right == MouseState::PRESSED) m_mouse.right = MouseState::DOWN;
}
