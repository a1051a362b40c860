// The sandbox's window (GLFW, no client API: Vulkan presents into it through
// gpu::Presenter). Collects GLFW's callbacks as InputEvents, owns mouse capture (hidden,
// unbounded cursor for mouse look) and turns the close button into an event, so the sandbox
// can warn about unsaved changes before closing.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "game/input.h"

struct GLFWwindow;

namespace game {

struct WindowOptions {
    std::string title = "vox";
    glm::uvec2 size{1280, 720};
    bool visible = true;
};

// Why no window can be opened here, in one line; empty when a display is present and can be
// opened (it is tried).
std::string displayProblem();

class Window {
public:
    static engine::Result<std::unique_ptr<Window>> create(const WindowOptions& options);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return mWindow; }
    glm::uvec2 framebufferSize() const;
    glm::uvec2 windowSize() const;

    // Processes pending window-system events and returns them in order.
    std::vector<InputEvent> pollEvents();
    void setCursorCaptured(bool captured);
    void setTitle(const std::string& title);
    void resize(glm::uvec2 size);

private:
    Window() = default;
    static void onKey(GLFWwindow* w, int key, int scancode, int action, int mods);
    static void onButton(GLFWwindow* w, int button, int action, int mods);
    static void onCursor(GLFWwindow* w, double x, double y);
    static void onScroll(GLFWwindow* w, double dx, double dy);
    static void onChar(GLFWwindow* w, unsigned codepoint);
    static void onClose(GLFWwindow* w);

    GLFWwindow* mWindow = nullptr;
    bool mCaptured = false;
    std::vector<InputEvent> mEvents;
};

}  // namespace game
