#include "game/script_player.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "core/number_check.h"
#include "core/quoted_string.h"

namespace game {

namespace {

// Mouse motion and cursor positions: far beyond any window, in pixels.
constexpr engine::NumberRange kPointerRange = engine::closedRange(-1e6, 1e6, "pixels");

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

bool parseFrame(const std::string& s, std::uint64_t& out) {
    const char* end = s.data() + s.size();
    auto r = std::from_chars(s.data(), end, out);
    return r.ec == std::errc() && r.ptr == end;
}

}  // namespace

engine::Result<ScriptPlayer> ScriptPlayer::parse(std::string_view text,
                                                 std::string_view sourceName) {
    ScriptPlayer player;
    std::istringstream in{std::string(text)};
    std::uint64_t previous = 0;
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::vector<std::string> w = words(line);
        if (w.empty()) continue;
        // `why` quotes the line's words: printable, so a stray control character cannot act.
        auto fail = [&](const std::string& why) {
            return engine::makeError("{}:{}: {}", sourceName, lineNo, engine::printableText(why));
        };
        if (w.size() < 2) return fail("expected 'FRAME COMMAND ...'");

        ScriptStep step;
        step.line = lineNo;
        bool relative = w[0][0] == '+';
        std::uint64_t frame = 0;
        if (!parseFrame(relative ? w[0].substr(1) : w[0], frame))
            return fail("'" + w[0] + "' is not a frame number");
        step.frame = relative ? previous + frame : frame;
        if (step.frame < previous)
            return fail("frame " + std::to_string(step.frame) +
                        " comes before the previous step's");
        previous = step.frame;

        const std::string& cmd = w[1];
        auto args = [&](std::size_t n) { return w.size() == n + 2; };
        auto key = [&](const std::string& name) -> engine::Result<int> {
            auto k = keyFromName(name);
            if (!k) return fail("unknown key '" + name + "'");
            return *k;
        };
        auto button = [&](const std::string& name) -> engine::Result<int> {
            auto b = mouseButtonFromName(name);
            if (!b) return fail("unknown mouse button '" + name + "' (left, right, middle)");
            return *b;
        };
        auto downUp = [&](const std::string& s) -> engine::Result<bool> {
            if (s == "down") return true;
            if (s == "up") return false;
            return fail("expected 'down' or 'up', got '" + s + "'");
        };
        // Every number goes through the one number check (core/number_check.h).
        auto number = [&](const std::string& word, std::string_view name,
                          const engine::NumberRange& range) -> engine::Result<float> {
            auto v = engine::parseNumber(fmt::format("{} {}", cmd, name), word, range);
            if (!v) return fail(v.error().message);
            return float(*v);
        };
        auto vec2 = [&](const engine::NumberRange& range) -> engine::Result<glm::vec2> {
            auto x = number(w[2], "x", range);
            if (!x) return x.error();
            auto y = number(w[3], "y", range);
            if (!y) return y.error();
            return glm::vec2(*x, *y);
        };
        auto push = [&](InputEventType type, int code, bool down, glm::vec2 value,
                        std::uint64_t at) {
            ScriptStep s = step;
            s.frame = at;
            s.event = {type, code, down, value};
            player.mSteps.push_back(s);
        };

        if ((cmd == "key" || cmd == "button") && args(2)) {
            auto code = cmd == "key" ? key(w[2]) : button(w[2]);
            if (!code) return code.error();
            auto down = downUp(w[3]);
            if (!down) return down.error();
            push(cmd == "key" ? InputEventType::Key : InputEventType::MouseButton, *code, *down, {},
                 step.frame);
        } else if ((cmd == "tap" || cmd == "click") && args(1)) {
            auto code = cmd == "tap" ? key(w[2]) : button(w[2]);
            if (!code) return code.error();
            InputEventType type = cmd == "tap" ? InputEventType::Key : InputEventType::MouseButton;
            push(type, *code, true, {}, step.frame);
            push(type, *code, false, {}, step.frame + 1);
        } else if ((cmd == "move" || cmd == "cursor") && args(2)) {
            auto v = vec2(kPointerRange);
            if (!v) return v.error();
            push(cmd == "move" ? InputEventType::MouseMove : InputEventType::CursorPos, 0, false,
                 *v, step.frame);
        } else if (cmd == "scroll" && args(1)) {
            auto dy = number(w[2], "steps", engine::closedRange(-1e4, 1e4, "steps"));
            if (!dy) return dy.error();
            push(InputEventType::Scroll, 0, false, {0.0f, *dy}, step.frame);
        } else if ((cmd == "screenshot" || cmd == "capture") && args(1)) {
            step.isAction = true;
            step.action = {
                cmd == "screenshot" ? ScriptAction::Kind::Screenshot : ScriptAction::Kind::Capture,
                w[2]};
            player.mSteps.push_back(step);
        } else if (cmd == "resize" && args(2)) {
            auto v = vec2(engine::wholeRange(1, 8192, "pixels"));
            if (!v) return v.error();
            step.isAction = true;
            step.action.kind = ScriptAction::Kind::Resize;
            step.action.size = glm::uvec2(*v);
            player.mSteps.push_back(step);
        } else if (cmd == "quit" && args(0)) {
            step.isAction = true;
            step.action = {ScriptAction::Kind::Quit, {}};
            player.mSteps.push_back(step);
        } else {
            return fail("unknown command or wrong arguments: '" + line +
                        "' (see game/script_player.h)");
        }
    }
    std::stable_sort(player.mSteps.begin(), player.mSteps.end(),
                     [](const ScriptStep& a, const ScriptStep& b) { return a.frame < b.frame; });
    return player;
}

engine::Result<ScriptPlayer> ScriptPlayer::load(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) return engine::makeError("{}: cannot open script", path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return parse(text.str(), path.string());
}

std::vector<InputEvent> ScriptPlayer::eventsFor(std::uint64_t frame) const {
    std::vector<InputEvent> out;
    for (const ScriptStep& s : mSteps) {
        if (s.frame == frame && !s.isAction) out.push_back(s.event);
    }
    return out;
}

std::vector<ScriptAction> ScriptPlayer::actionsFor(std::uint64_t frame) const {
    std::vector<ScriptAction> out;
    for (const ScriptStep& s : mSteps) {
        if (s.frame == frame && s.isAction) out.push_back(s.action);
    }
    return out;
}

}  // namespace game
