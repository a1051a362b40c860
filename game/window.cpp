#include "game/window.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <cstdlib>

namespace game {

namespace {

std::string gGlfwError;

void onGlfwError(int, const char* description) {
    gGlfwError = description ? description : "unknown GLFW error";
}

Window* self(GLFWwindow* w) { return static_cast<Window*>(glfwGetWindowUserPointer(w)); }

}  // namespace

std::string displayProblem() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland))
        return "no display (DISPLAY and WAYLAND_DISPLAY are unset)";
    // Set is not the same as reachable: try it. GLFW stays initialised for the window that
    // follows (glfwInit again is a no-op): closing the only connection would make an X server
    // without -noreset (Xvfb's default) reset, and the window's connection could race it.
    glfwSetErrorCallback(&onGlfwError);
    if (!glfwInit()) return "cannot open the display: " + gGlfwError;
    if (!glfwVulkanSupported()) return "the display has no Vulkan presentation support";
    return {};
}

engine::Result<std::unique_ptr<Window>> Window::create(const WindowOptions& options) {
    if (std::string why = displayProblem(); !why.empty()) return engine::Error{why};
    glfwSetErrorCallback(&onGlfwError);
    if (!glfwInit()) return engine::makeError("cannot open the display: {}", gGlfwError);
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        return engine::makeError("the display has no Vulkan presentation support (GLFW: {})",
                                 gGlfwError);
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    std::unique_ptr<Window> window(new Window());
    window->mWindow = glfwCreateWindow(int(options.size.x), int(options.size.y),
                                       options.title.c_str(), nullptr, nullptr);
    if (!window->mWindow) {
        glfwTerminate();
        return engine::makeError("cannot create a window: {}", gGlfwError);
    }
    GLFWwindow* w = window->mWindow;
    glfwSetWindowUserPointer(w, window.get());
    glfwSetKeyCallback(w, &Window::onKey);
    glfwSetMouseButtonCallback(w, &Window::onButton);
    glfwSetCursorPosCallback(w, &Window::onCursor);
    glfwSetScrollCallback(w, &Window::onScroll);
    glfwSetCharCallback(w, &Window::onChar);
    glfwSetWindowCloseCallback(w, &Window::onClose);
    if (glfwRawMouseMotionSupported()) glfwSetInputMode(w, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    return window;
}

Window::~Window() {
    if (mWindow) glfwDestroyWindow(mWindow);
    glfwTerminate();
}

glm::uvec2 Window::framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(mWindow, &w, &h);
    return {unsigned(std::max(w, 0)), unsigned(std::max(h, 0))};
}

glm::uvec2 Window::windowSize() const {
    int w = 0, h = 0;
    glfwGetWindowSize(mWindow, &w, &h);
    return {unsigned(std::max(w, 0)), unsigned(std::max(h, 0))};
}

std::vector<InputEvent> Window::pollEvents() {
    glfwPollEvents();
    std::vector<InputEvent> out;
    out.swap(mEvents);
    return out;
}

void Window::setCursorCaptured(bool captured) {
    if (captured == mCaptured) return;
    mCaptured = captured;
    glfwSetInputMode(mWindow, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
}

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(mWindow, title.c_str()); }

void Window::resize(glm::uvec2 size) { glfwSetWindowSize(mWindow, int(size.x), int(size.y)); }

void Window::onKey(GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_REPEAT || key == GLFW_KEY_UNKNOWN) return;
    self(w)->mEvents.push_back({InputEventType::Key, key, action == GLFW_PRESS, {}});
}

void Window::onButton(GLFWwindow* w, int button, int action, int) {
    self(w)->mEvents.push_back({InputEventType::MouseButton, button, action == GLFW_PRESS, {}});
}

void Window::onCursor(GLFWwindow* w, double x, double y) {
    self(w)->mEvents.push_back({InputEventType::CursorPos, 0, false, {float(x), float(y)}});
}

void Window::onScroll(GLFWwindow* w, double dx, double dy) {
    self(w)->mEvents.push_back({InputEventType::Scroll, 0, false, {float(dx), float(dy)}});
}

void Window::onChar(GLFWwindow* w, unsigned codepoint) {
    self(w)->mEvents.push_back({InputEventType::Char, int(codepoint), false, {}});
}

void Window::onClose(GLFWwindow* w) {
    // The sandbox decides (it may warn about unsaved changes first).
    glfwSetWindowShouldClose(w, GLFW_FALSE);
    self(w)->mEvents.push_back({InputEventType::Close, 0, false, {}});
}

}  // namespace game
