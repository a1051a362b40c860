// Fly camera: WASD moves in the view plane, Q/E down/up along world Y, mouse motion turns
// (yaw about world Y, pitch clamped short of the poles), Shift is fast and Alt slow. Scene
// file presets set position and view; preset() hands the current view to the renderer.
// Time is passed in, so a script's fixed step gives the same path on every run.
#pragma once

#include <glm/glm.hpp>

#include "game/input.h"
#include "world/scene.h"

namespace game {

struct CameraSettings {
    float speed = 24.0f;            // voxels per second
    float fastMultiplier = 4.0f;    // with Shift
    float slowMultiplier = 0.25f;   // with Alt
    float degreesPerPixel = 0.15f;  // mouse look
};

class CameraController {
public:
    explicit CameraController(CameraSettings settings = {}) : mSettings(settings) {}

    void setFromPreset(const engine::world::CameraPreset& preset);
    // The current view as a preset (target one unit ahead).
    engine::world::CameraPreset preset() const;

    // Moves with the held keys over `dt` seconds; turns with the mouse when `mouseLook`.
    void update(const InputState& input, float dt, bool mouseLook);
    // Turns with the mouse only (walk mode moves the camera itself: game/walk_controller.h).
    void look(const InputState& input, bool mouseLook);
    void setPosition(glm::vec3 position) { mPosition = position; }

    glm::vec3 position() const { return mPosition; }
    glm::vec3 forward() const;
    glm::vec3 right() const;
    float yawDegrees() const { return mYaw; }
    CameraSettings& settings() { return mSettings; }

private:
    CameraSettings mSettings;
    glm::vec3 mPosition{0.0f};
    float mYaw = 0.0f;    // degrees, 0 looks along +Z, 90 along +X
    float mPitch = 0.0f;  // degrees, positive looks up
    float mFovY = 60.0f;
    std::string mName = "sandbox";
};

}  // namespace game
