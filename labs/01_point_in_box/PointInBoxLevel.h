// PointInBoxLevel.h - boxes you can point at, pick up and drag, through a zoomable camera.
//
// The boxes live in "scene" coordinates. The camera (getCamera) scales the scene about the
// middle of the window when you zoom, so on screen a box can be somewhere else than its
// scene position says. Input gives the mouse in window (world) coordinates; the level turns
// it into scene coordinates before testing it against the boxes.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics/Transform.hpp>

#include <string>
#include <vector>

class PointInBoxLevel : public hitbox::Level
{
public:
    // "No box": what getHoveredBox/getSelectedBox answer when the mouse is over nothing.
    static constexpr int noBox = -1;
    // Each mouse-wheel notch (or +/- key) zooms by this factor, between the two limits.
    static constexpr float zoomStep = 1.25f;
    static constexpr float minZoom = 0.5f;
    static constexpr float maxZoom = 3.f;

    PointInBoxLevel();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // What the player sees, for the screen and for the grading tests.
    int getBoxCount() const;
    const hitbox::GameObject& getBox(int index) const;
    int getHoveredBox() const;  // the box under the mouse, or noBox
    int getSelectedBox() const; // the box being dragged, or noBox
    float getZoom() const;
    // Scene coordinates to window coordinates: how the boxes are drawn.
    sf::Transform getCamera() const;
    sf::Vector2f getMouseInScene() const;
    // The star (task 4): its corners in scene coordinates, and whether the mouse is inside it.
    const std::vector<sf::Vector2f>& getStar() const;
    bool isStarHovered() const;

    // The three steps of update(), one per task (the grading tests call each on its own).
    // Task 1: the index of the top box containing the scene point, or noBox.
    int findBoxUnder(sf::Vector2f scenePoint);
    // Task 2: picks up, drags or drops a box, given the box under the mouse and the mouse in
    // scene coordinates; the button is the one the last handleInput saw.
    void dragBox(int boxUnderMouse, sf::Vector2f mouse);
    // Task 3: a point of the window to the scene point drawn there (undoes getCamera).
    sf::Vector2f windowToScene(sf::Vector2f windowPoint) const;

private:
    std::vector<hitbox::GameObject> boxes;
    float zoom = 1.f;

    // The mouse as the last input step saw it. It starts over the second box so that a
    // --screenshot shows a highlighted box; it follows the real mouse once that moves.
    sf::Vector2f mouseInWindow{455.f, 240.f};
    sf::Vector2f lastMouseReading;
    bool mouseDown = false;
    bool mousePressed = false; // went down in this step

    sf::Vector2f mouseInScene;
    int hoveredBox = noBox;
    int selectedBox = noBox;

    std::vector<sf::Vector2f> star; // a concave polygon (task 4), scene coordinates
    bool starHovered = false;
    sf::Vector2f grabOffset; // from the mouse to the dragged box's position
};
