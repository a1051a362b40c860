// Where the HUD's panels go for a window size, with no ImGui in sight so it can be tested:
// the rectangles never overlap and stay inside the window from 320x180 to 4K. Below a size
// threshold the two panels collapse to one compact strip (taller in a narrow, tall window, where
// its figures wrap onto more lines); on tall windows the font scales up
// by whole steps (the built-in bitmap font stays crisp). Also the two text helpers the HUD
// needs to stay inside those rectangles: wrapping a list of entries only between entries (a
// number is never split), and the palette grid that scrolls instead of growing.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace game {

struct HudRect {
    glm::vec2 min{0.0f}, size{0.0f};
    bool empty() const { return size.x <= 0.0f || size.y <= 0.0f; }
    glm::vec2 max() const { return min + size; }
};

// True when a and b share area (touching edges do not count); empty rectangles never overlap.
bool overlaps(const HudRect& a, const HudRect& b);
// True when r lies within [0, window].
bool inside(const HudRect& r, glm::vec2 window);

struct HudLayout {
    float fontScale = 1.0f;
    bool compact = false;  // one strip of key figures instead of the stats and edit panels
    // The most each window may take; the windows auto-size within them and scroll beyond.
    HudRect stats, tools, keys, message;  // tools is empty when compact, keys when hidden
};

// Window size below which (in pixels at font scale 1) the HUD is compact.
inline constexpr glm::vec2 kCompactBelow{560.0f, 300.0f};

// lineHeight: one text line with its spacing at font scale 1 (ImGui: font size + item spacing).
HudLayout layoutHud(glm::vec2 window, float lineHeight, bool showKeys, bool message);

// Joins entries with `separator` into lines no wider than maxWidth (as measured by `width`),
// breaking only between entries; an entry wider than maxWidth gets a line of its own.
std::vector<std::string> wrapEntries(const std::vector<std::string>& entries,
                                     std::string_view separator, float maxWidth,
                                     const std::function<float(std::string_view)>& width);

struct PaletteGrid {
    int columns = 1;
    int rows = 0;         // all rows
    int visibleRows = 0;  // rows shown at once; the rest scroll
    bool scrolls() const { return visibleRows < rows; }
};

// Swatches of `cell` pixels (with spacing) in at most `width` x `height`: at most 8 columns, at
// least one column and, when there is anything to show, at least one visible row.
PaletteGrid paletteGrid(int count, float width, float height, float cell);

}  // namespace game
