#include "game/camera_controller.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <cmath>

namespace game {

namespace {
constexpr float kMaxPitch = 89.0f;  // the renderer's basis degenerates looking straight up or down
}

void CameraController::setFromPreset(const engine::world::CameraPreset& preset) {
    mPosition = preset.position;
    glm::vec3 d = glm::normalize(preset.target - preset.position);
    mYaw = glm::degrees(std::atan2(d.x, d.z));
    mPitch =
        std::clamp(glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))), -kMaxPitch, kMaxPitch);
    mFovY = preset.fovYDegrees;
    mName = preset.name;
}

engine::world::CameraPreset CameraController::preset() const {
    engine::world::CameraPreset p;
    p.name = mName;
    p.position = mPosition;
    p.target = mPosition + forward();
    p.fovYDegrees = mFovY;
    return p;
}

glm::vec3 CameraController::forward() const {
    float yaw = glm::radians(mYaw), pitch = glm::radians(mPitch);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

glm::vec3 CameraController::right() const {
    // Matches the renderer's basis: right = forward x up.
    float yaw = glm::radians(mYaw);
    return {-std::cos(yaw), 0.0f, std::sin(yaw)};
}

void CameraController::look(const InputState& input, bool mouseLook) {
    if (!mouseLook) return;
    glm::vec2 d = input.mouseDelta() * mSettings.degreesPerPixel;
    mYaw = std::fmod(mYaw - d.x, 360.0f);
    mPitch = std::clamp(mPitch - d.y, -kMaxPitch, kMaxPitch);
}

void CameraController::update(const InputState& input, float dt, bool mouseLook) {
    look(input, mouseLook);
    if (input.ctrl()) return;  // Ctrl+S saves, it does not step back
    glm::vec3 move(0.0f);
    glm::vec3 f = forward(), r = right();
    if (input.held(GLFW_KEY_W)) move += f;
    if (input.held(GLFW_KEY_S)) move -= f;
    if (input.held(GLFW_KEY_D)) move += r;
    if (input.held(GLFW_KEY_A)) move -= r;
    if (input.held(GLFW_KEY_E)) move.y += 1.0f;
    if (input.held(GLFW_KEY_Q)) move.y -= 1.0f;
    if (glm::dot(move, move) == 0.0f) return;
    float speed = mSettings.speed;
    if (input.shift()) speed *= mSettings.fastMultiplier;
    if (input.alt()) speed *= mSettings.slowMultiplier;
    mPosition += glm::normalize(move) * speed * dt;
}

}  // namespace game
