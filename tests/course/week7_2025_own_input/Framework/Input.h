#pragma once
#pragma warning(push)
#pragma warning(disable : 4275 4251)
#include <SFML/Window/Keyboard.hpp>
#pragma warning(pop)
#include <array>

// Input class
// Stores the keyboard (by Scancode) and mouse state that Main.cpp reads from the window's
// events. Call update() at the end of every frame.
class Input
{
public:
	enum class MouseState { UP, DOWN, PRESSED };

	void setKeyDown(sf::Keyboard::Scancode key);
	void setKeyUp(sf::Keyboard::Scancode key);
	bool isKeyDown(sf::Keyboard::Scancode key) const;
	bool isPressed(sf::Keyboard::Scancode key) const;

	void setMouseX(int x);
	void setMouseY(int y);
	void setMousePosition(int x, int y);
	int getMouseX() const;
	int getMouseY() const;

	void setLeftMouse(MouseState state);
	bool isLeftMouseDown() const;
	bool isLeftMousePressed() const;
	void setRightMouse(MouseState state);
	bool isRightMouseDown() const;
	bool isRightMousePressed() const;

	void update();

private:
	struct Mouse
	{
		int x = 0;
		int y = 0;
		MouseState left = MouseState::UP;
		MouseState right = MouseState::UP;
	};

	std::array<bool, sf::Keyboard::ScancodeCount> m_keys{};
	std::array<bool, sf::Keyboard::ScancodeCount> m_pressed{};
	Mouse m_mouse;
};
