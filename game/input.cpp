#include "game/input.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <cctype>
#include <utility>

namespace game {

void InputState::beginFrame() {
    mPressed.fill(false);
    mButtonPressed.fill(false);
    mButtonReleased.fill(false);
    mMouseDelta = glm::vec2(0.0f);
    mScroll = 0.0f;
    mChars.clear();
    mClose = false;
}

void InputState::apply(const InputEvent& e) {
    switch (e.type) {
        case InputEventType::Key:
            if (!valid(e.code)) return;
            if (e.down && !mKeys[e.code]) mPressed[e.code] = true;
            mKeys[e.code] = e.down;
            break;
        case InputEventType::MouseButton:
            if (!validButton(e.code)) return;
            if (e.down && !mButtons[e.code]) mButtonPressed[e.code] = true;
            if (!e.down && mButtons[e.code]) mButtonReleased[e.code] = true;
            mButtons[e.code] = e.down;
            break;
        case InputEventType::MouseMove:
            mMouseDelta += e.value;
            mCursor += e.value;
            break;
        case InputEventType::CursorPos:
            if (mHasCursor) mMouseDelta += e.value - mCursor;
            mCursor = e.value;
            mHasCursor = true;
            break;
        case InputEventType::Scroll:
            mScroll += e.value.y;
            break;
        case InputEventType::Char:
            mChars.push_back(static_cast<unsigned>(e.code));
            break;
        case InputEventType::Close:
            mClose = true;
            break;
    }
}

bool InputState::ctrl() const {
    return held(GLFW_KEY_LEFT_CONTROL) || held(GLFW_KEY_RIGHT_CONTROL);
}
bool InputState::shift() const { return held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT); }
bool InputState::alt() const { return held(GLFW_KEY_LEFT_ALT) || held(GLFW_KEY_RIGHT_ALT); }

namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

}  // namespace

std::optional<int> keyFromName(std::string_view name) {
    if (name.size() == 1) {
        char c = char(std::toupper(static_cast<unsigned char>(name[0])));
        if (c >= 'A' && c <= 'Z') return GLFW_KEY_A + (c - 'A');
        if (c >= '0' && c <= '9') return GLFW_KEY_0 + (c - '0');
    }
    static const std::pair<const char*, int> kNames[] = {
        {"space", GLFW_KEY_SPACE},
        {"escape", GLFW_KEY_ESCAPE},
        {"esc", GLFW_KEY_ESCAPE},
        {"enter", GLFW_KEY_ENTER},
        {"tab", GLFW_KEY_TAB},
        {"backspace", GLFW_KEY_BACKSPACE},
        {"delete", GLFW_KEY_DELETE},
        {"up", GLFW_KEY_UP},
        {"down", GLFW_KEY_DOWN},
        {"left", GLFW_KEY_LEFT},
        {"right", GLFW_KEY_RIGHT},
        {"leftshift", GLFW_KEY_LEFT_SHIFT},
        {"rightshift", GLFW_KEY_RIGHT_SHIFT},
        {"leftctrl", GLFW_KEY_LEFT_CONTROL},
        {"rightctrl", GLFW_KEY_RIGHT_CONTROL},
        {"ctrl", GLFW_KEY_LEFT_CONTROL},
        {"shift", GLFW_KEY_LEFT_SHIFT},
        {"alt", GLFW_KEY_LEFT_ALT},
        {"leftalt", GLFW_KEY_LEFT_ALT},
        {"rightalt", GLFW_KEY_RIGHT_ALT},
        {"[", GLFW_KEY_LEFT_BRACKET},
        {"]", GLFW_KEY_RIGHT_BRACKET},
        {",", GLFW_KEY_COMMA},
        {".", GLFW_KEY_PERIOD},
        {"-", GLFW_KEY_MINUS},
        {"=", GLFW_KEY_EQUAL},
        {"pageup", GLFW_KEY_PAGE_UP},
        {"pagedown", GLFW_KEY_PAGE_DOWN},
        {"home", GLFW_KEY_HOME},
        {"end", GLFW_KEY_END},
    };
    std::string n = lower(name);
    for (const auto& [k, code] : kNames) {
        if (n == k) return code;
    }
    if (n.size() >= 2 && n.size() <= 3 && n[0] == 'f' &&
        n.find_first_not_of("0123456789", 1) == std::string::npos && n[1] != '0') {
        int f = std::atoi(n.c_str() + 1);
        if (f >= 1 && f <= 12) return GLFW_KEY_F1 + (f - 1);
    }
    return std::nullopt;
}

std::optional<int> mouseButtonFromName(std::string_view name) {
    std::string n = lower(name);
    if (n == "left") return GLFW_MOUSE_BUTTON_LEFT;
    if (n == "right") return GLFW_MOUSE_BUTTON_RIGHT;
    if (n == "middle") return GLFW_MOUSE_BUTTON_MIDDLE;
    return std::nullopt;
}

}  // namespace game
