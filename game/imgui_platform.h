// Dear ImGui's platform side for the sandbox: owns the ImGui context and feeds it from the
// sandbox's InputState rather than from GLFW, so the HUD reacts to scripted input exactly as
// to live input. (ImGui's own GLFW backend reads the window directly, which a script cannot
// drive.) The draw side is gpu::ImGuiOverlay.
#pragma once

#include <glm/glm.hpp>

#include "game/input.h"

namespace game {

class ImGuiPlatform {
public:
    ImGuiPlatform();
    ~ImGuiPlatform();
    ImGuiPlatform(const ImGuiPlatform&) = delete;
    ImGuiPlatform& operator=(const ImGuiPlatform&) = delete;

    // Starts an ImGui frame. `cursorScale` maps window to framebuffer pixels; with
    // `cursorVisible` false (mouse look) the HUD sees no cursor and no clicks.
    void newFrame(const InputState& input, glm::uvec2 framebufferSize, glm::vec2 cursorScale,
                  float dt, bool cursorVisible);
    // True when the cursor is over the HUD (clicks go to it, not to the world).
    bool wantsMouse() const;
};

}  // namespace game
