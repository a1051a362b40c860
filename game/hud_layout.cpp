#include "game/hud_layout.h"

#include <algorithm>
#include <cmath>

namespace game {

namespace {

constexpr float kMargin = 8.0f;   // between panels and from the window's edge, at scale 1
constexpr float kPadding = 8.0f;  // a window's inner padding (ImGui's default), at scale 1

}  // namespace

bool overlaps(const HudRect& a, const HudRect& b) {
    if (a.empty() || b.empty()) return false;
    return a.min.x < b.max().x && b.min.x < a.max().x && a.min.y < b.max().y && b.min.y < a.max().y;
}

bool inside(const HudRect& r, glm::vec2 window) {
    return r.empty() ||
           (r.min.x >= 0.0f && r.min.y >= 0.0f && r.max().x <= window.x && r.max().y <= window.y);
}

HudLayout layoutHud(glm::vec2 window, float lineHeight, bool showKeys, bool message) {
    HudLayout l;
    // Whole steps from 1080 lines up: 2 at 4K, so text keeps its physical size.
    l.fontScale = std::max(1.0f, std::floor(std::min(window.y / 1080.0f, window.x / 1920.0f)));
    glm::vec2 scaled = window / l.fontScale;
    l.compact = scaled.x < kCompactBelow.x || scaled.y < kCompactBelow.y;
    const float s = l.fontScale;
    const float margin = (l.compact ? kMargin * 0.5f : kMargin) * s;
    const float line = lineHeight * s, pad = 2.0f * kPadding * s;

    float bottom = window.y - margin;  // the lowest row panels may use
    if (message) {
        // Up to two lines: a long message wraps rather than running under a panel.
        float h = std::min(2.0f * line + pad, window.y * 0.3f);
        l.message = {{margin, bottom - h}, {window.x - 2.0f * margin, h}};
        bottom = l.message.min.y - margin;
    }
    const float top = margin;
    const float height = std::max(0.0f, bottom - top);

    if (l.compact) {
        // A strip on top: four lines, or as many as half the height holds (a narrow window wraps
        // its figures onto more lines, and a tall one has the room); it auto-sizes to what it
        // shows. The keys (F1) go below it, and then the strip keeps one line (asked for, the keys
        // matter more than the figures).
        const float lines =
            showKeys ? 1.0f : std::max(4.0f, std::floor((0.5f * height - pad) / line));
        float stripH = std::min(height, lines * line + pad);
        l.stats = {{margin, top}, {window.x - 2.0f * margin, stripH}};
        if (showKeys) {
            float keysTop = top + stripH + margin;
            l.keys = {{margin, keysTop},
                      {window.x - 2.0f * margin, std::max(0.0f, bottom - keysTop)}};
        }
        return l;
    }
    // Two columns: stats on the left (keys under them when shown), edit tools on the right.
    const float column = (window.x - 3.0f * margin) * 0.5f;
    l.tools = {{window.x - margin - column, top}, {column, height}};
    if (showKeys) {
        float statsH = std::floor((height - margin) * 0.55f);
        l.stats = {{margin, top}, {column, statsH}};
        l.keys = {{margin, top + statsH + margin}, {column, height - statsH - margin}};
    } else {
        l.stats = {{margin, top}, {column, height}};
    }
    return l;
}

std::vector<std::string> wrapEntries(const std::vector<std::string>& entries,
                                     std::string_view separator, float maxWidth,
                                     const std::function<float(std::string_view)>& width) {
    std::vector<std::string> lines;
    std::string current;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        // The separator stays with the entry it follows, so a line never starts with one.
        std::string piece =
            entries[i] + (i + 1 < entries.size() ? std::string(separator) : std::string());
        if (!current.empty() && width(current + piece) > maxWidth) {
            lines.push_back(current);
            current.clear();
        }
        current += piece;
    }
    if (!current.empty()) lines.push_back(current);
    // Trailing separator spaces would only widen the line.
    for (std::string& line : lines)
        while (!line.empty() && line.back() == ' ') line.pop_back();
    return lines;
}

PaletteGrid paletteGrid(int count, float width, float height, float cell) {
    PaletteGrid g;
    if (count <= 0) return g;
    g.columns = std::clamp(static_cast<int>(std::floor(width / cell)), 1, 8);
    g.rows = (count + g.columns - 1) / g.columns;
    g.visibleRows = std::clamp(static_cast<int>(std::floor(height / cell)), 1, g.rows);
    return g;
}

}  // namespace game
