#include "game/imgui_platform.h"

#include <GLFW/glfw3.h>
#include <cfloat>
#include <imgui.h>

namespace game {

ImGuiPlatform::ImGuiPlatform() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini: window layout is the HUD's, and runs repeat
    io.LogFilename = nullptr;
    io.BackendPlatformName = "vox_input_state";
    const int map[][2] = {
        {ImGuiKey_Tab, GLFW_KEY_TAB},
        {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
        {ImGuiKey_RightArrow, GLFW_KEY_RIGHT},
        {ImGuiKey_UpArrow, GLFW_KEY_UP},
        {ImGuiKey_DownArrow, GLFW_KEY_DOWN},
        {ImGuiKey_PageUp, GLFW_KEY_PAGE_UP},
        {ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN},
        {ImGuiKey_Home, GLFW_KEY_HOME},
        {ImGuiKey_End, GLFW_KEY_END},
        {ImGuiKey_Insert, GLFW_KEY_INSERT},
        {ImGuiKey_Delete, GLFW_KEY_DELETE},
        {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
        {ImGuiKey_Space, GLFW_KEY_SPACE},
        {ImGuiKey_Enter, GLFW_KEY_ENTER},
        {ImGuiKey_Escape, GLFW_KEY_ESCAPE},
        {ImGuiKey_A, GLFW_KEY_A},
        {ImGuiKey_C, GLFW_KEY_C},
        {ImGuiKey_V, GLFW_KEY_V},
        {ImGuiKey_X, GLFW_KEY_X},
        {ImGuiKey_Y, GLFW_KEY_Y},
        {ImGuiKey_Z, GLFW_KEY_Z},
    };
    for (const auto& [imguiKey, glfwKey] : map) io.KeyMap[imguiKey] = glfwKey;
    // Build the font atlas now, so a frame can be built even when nothing draws it.
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.0f;
}

ImGuiPlatform::~ImGuiPlatform() { ImGui::DestroyContext(); }

void ImGuiPlatform::newFrame(const InputState& input, glm::uvec2 framebufferSize,
                             glm::vec2 cursorScale, float dt, bool cursorVisible) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(framebufferSize.x), float(framebufferSize.y));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = dt > 0.0f ? dt : 1.0f / 60.0f;
    if (cursorVisible) {
        glm::vec2 p = input.cursor() * cursorScale;
        io.MousePos = ImVec2(p.x, p.y);
    } else {
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    }
    for (int b = 0; b < 3; ++b)
        io.MouseDown[b] = cursorVisible && (input.buttonHeld(b) || input.buttonPressed(b));
    io.MouseWheel = cursorVisible ? input.scroll() : 0.0f;
    for (int k = 0; k < InputState::kMaxKeys; ++k)
        io.KeysDown[k] = input.held(k) || input.pressed(k);
    io.KeyCtrl = input.ctrl();
    io.KeyShift = input.shift();
    io.KeyAlt = input.alt();
    io.KeySuper = false;
    for (unsigned c : input.chars()) io.AddInputCharacter(c);
}

bool ImGuiPlatform::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

}  // namespace game
