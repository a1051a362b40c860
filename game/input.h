// Input for the sandbox: the events a frame receives (from the window, or replayed from a
// script) and the state they leave — keys and buttons held, pressed or released this frame,
// mouse motion, cursor, scroll. Key and button codes are GLFW's; scripts name them
// (keyFromName). Everything downstream reads an InputState, never the window, so scripted and
// live input take the same path.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace game {

enum class InputEventType {
    Key,          // code = key, down
    MouseButton,  // code = button, down
    MouseMove,    // value = motion in window pixels (mouse look)
    CursorPos,    // value = cursor position in window pixels
    Scroll,       // value.y = wheel steps
    Char,         // code = Unicode code point (text for the HUD)
    Close,        // the window's close button
};

struct InputEvent {
    InputEventType type = InputEventType::Key;
    int code = 0;
    bool down = false;
    glm::vec2 value{0.0f};
};

class InputState {
public:
    static constexpr int kMaxKeys = 512;
    static constexpr int kMaxButtons = 8;

    // Clears this frame's edges, motion and scroll; held keys stay held.
    void beginFrame();
    void apply(const InputEvent& event);
    // The next cursor position starts a new track (after capturing or releasing the mouse,
    // GLFW moves the cursor: that jump is not motion).
    void resetCursorTracking() { mHasCursor = false; }

    bool held(int key) const { return valid(key) && mKeys[key]; }
    bool pressed(int key) const { return valid(key) && mPressed[key]; }
    bool buttonHeld(int b) const { return validButton(b) && mButtons[b]; }
    bool buttonPressed(int b) const { return validButton(b) && mButtonPressed[b]; }
    bool buttonReleased(int b) const { return validButton(b) && mButtonReleased[b]; }
    bool ctrl() const;
    bool shift() const;
    bool alt() const;

    glm::vec2 mouseDelta() const { return mMouseDelta; }
    glm::vec2 cursor() const { return mCursor; }
    float scroll() const { return mScroll; }
    const std::vector<unsigned>& chars() const { return mChars; }
    bool closeRequested() const { return mClose; }

private:
    static bool valid(int key) { return key >= 0 && key < kMaxKeys; }
    static bool validButton(int b) { return b >= 0 && b < kMaxButtons; }

    std::array<bool, kMaxKeys> mKeys{}, mPressed{};
    std::array<bool, kMaxButtons> mButtons{}, mButtonPressed{}, mButtonReleased{};
    glm::vec2 mMouseDelta{0.0f};
    glm::vec2 mCursor{0.0f};
    bool mHasCursor = false;
    float mScroll = 0.0f;
    std::vector<unsigned> mChars;
    bool mClose = false;
};

// Names used by scripts and the key list: letters and digits as themselves, "Space",
// "Escape", "Enter", "Tab", "Backspace", "Delete", "Up"/"Down"/"Left"/"Right", "F1".."F12",
// "LeftShift", "RightShift", "LeftCtrl", "RightCtrl", "LeftAlt", "RightAlt", "[", "]",
// ",", ".", "-", "=", "PageUp", "PageDown", "Home", "End". Case-insensitive.
std::optional<int> keyFromName(std::string_view name);
// "left", "right", "middle".
std::optional<int> mouseButtonFromName(std::string_view name);

}  // namespace game
