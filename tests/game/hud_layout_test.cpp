// The HUD's layout (game/hud_layout.h): panels inside the window and never overlapping from
// 320x180 to 4K, entries wrapped only between entries, long palettes scrolling in a bounded grid.
#include "game/hud_layout.h"

#include <gtest/gtest.h>
#include <regex>

using game::HudLayout;
using game::HudRect;

namespace {

constexpr float kLine = 17.0f;  // ImGui's default font (13 px) plus item spacing (4 px)

std::vector<HudRect> panels(const HudLayout& l) { return {l.stats, l.tools, l.keys, l.message}; }

void expectClean(glm::vec2 window, bool keys, bool message) {
    SCOPED_TRACE(testing::Message() << window.x << "x" << window.y << (keys ? " keys" : "")
                                    << (message ? " message" : ""));
    HudLayout l = game::layoutHud(window, kLine, keys, message);
    auto r = panels(l);
    for (std::size_t i = 0; i < r.size(); ++i) {
        EXPECT_TRUE(game::inside(r[i], window)) << "panel " << i;
        for (std::size_t j = i + 1; j < r.size(); ++j)
            EXPECT_FALSE(game::overlaps(r[i], r[j])) << "panels " << i << ", " << j;
    }
    // The stats always get room for at least one line; a message for at least one; keys too.
    EXPECT_GE(l.stats.size.y, kLine * l.fontScale);
    if (message) {
        EXPECT_GE(l.message.size.y, kLine * l.fontScale);
    }
    if (keys) {
        EXPECT_GE(l.keys.size.y, kLine * l.fontScale);
    }
    if (!l.compact) {
        EXPECT_FALSE(l.tools.empty());
    }
}

}  // namespace

TEST(HudLayout, PanelsInsideAndApartAtTheNamedSizes) {
    for (glm::vec2 w :
         {glm::vec2(320, 180), glm::vec2(640, 360), glm::vec2(1280, 720), glm::vec2(3840, 2160)})
        for (bool keys : {false, true})
            for (bool message : {false, true}) expectClean(w, keys, message);
}

TEST(HudLayout, PanelsInsideAndApartAtEverySizeBetween) {
    for (float x = 320; x <= 3840; x += 97)
        for (float y = 180; y <= 2160; y += 61) {
            expectClean({x, y}, false, true);
            expectClean({x, y}, true, true);
        }
}

TEST(HudLayout, CompactBelowTheThresholdAndScaledAt4K) {
    HudLayout tiny = game::layoutHud({320, 180}, kLine, false, false);
    EXPECT_TRUE(tiny.compact);
    EXPECT_TRUE(tiny.tools.empty());
    EXPECT_EQ(tiny.fontScale, 1.0f);
    HudLayout small = game::layoutHud({640, 360}, kLine, false, false);
    EXPECT_FALSE(small.compact);  // two panels side by side, apart
    EXPECT_LE(small.stats.max().x, small.tools.min.x);
    HudLayout uhd = game::layoutHud({3840, 2160}, kLine, false, false);
    EXPECT_FALSE(uhd.compact);
    EXPECT_EQ(uhd.fontScale, 2.0f);
}

TEST(HudLayout, WrapsOnlyBetweenEntries) {
    // Pass names with their milliseconds, as the HUD shows them with --indirect cache.
    std::vector<std::string> entries = {
        "primary 1.25",        "shadow 0.50",       "restir initial 12.75", "restir temporal 3.00",
        "cache update 20.125", "cache gather 4.50", "denoise 7.25",         "tonemap 0.10"};
    auto chars = [](std::string_view s) {
        return static_cast<float>(s.size()) * 7.0f;
    };  // 7 px per glyph
    for (float maxWidth : {7.0f, 70.0f, 100.0f, 140.0f, 168.0f, 200.0f, 300.0f, 1000.0f}) {
        SCOPED_TRACE(maxWidth);
        auto lines = game::wrapEntries(entries, ", ", maxWidth, chars);
        std::string joined;
        for (const std::string& line : lines) {
            // A line is whole entries: it never starts or ends inside "name number".
            std::regex whole(R"(^[a-z ]+ \d+\.\d+(, [a-z ]+ \d+\.\d+)*,?$)");
            EXPECT_TRUE(std::regex_match(line, whole)) << "'" << line << "'";
            // Wider than allowed only when the line is one entry.
            if (chars(line) > maxWidth) {
                EXPECT_EQ(line.find(", "), std::string::npos) << line;
            }
            joined += (joined.empty() ? "" : " ") + line;
        }
        std::string expected;
        for (std::size_t i = 0; i < entries.size(); ++i)
            expected += entries[i] + (i + 1 < entries.size() ? ", " : "");
        EXPECT_EQ(joined, expected);  // nothing lost, nothing reordered
    }
    EXPECT_EQ(game::wrapEntries(entries, ", ", 1000.0f, chars).size(), 1u);
    EXPECT_TRUE(game::wrapEntries({}, ", ", 100.0f, chars).empty());
}

TEST(HudLayout, ThreeHundredMaterialsScrollInsideTheirBox) {
    const float cell = 23.0f;  // a swatch (19 px) plus spacing
    for (glm::vec2 box :
         {glm::vec2(40, 30), glm::vec2(150, 100), glm::vec2(300, 400), glm::vec2(1800, 600)}) {
        game::PaletteGrid g = game::paletteGrid(300, box.x, box.y, cell);
        EXPECT_EQ(g.rows, (300 + g.columns - 1) / g.columns);
        EXPECT_GE(g.columns * g.rows, 300);
        EXPECT_GE(g.visibleRows, 1);
        EXPECT_LE(g.visibleRows * cell, std::max(box.y, cell)) << box.x << "x" << box.y;
        EXPECT_LE(g.columns * cell, std::max(box.x, cell));
        EXPECT_TRUE(g.scrolls());
    }
    game::PaletteGrid few = game::paletteGrid(9, 300, 400, cell);
    EXPECT_EQ(few.columns, 8);
    EXPECT_EQ(few.rows, 2);
    EXPECT_FALSE(few.scrolls());
}

TEST(HudLayout, CompactStripInANarrowTallWindowHasRoomForAllItsLines) {
    // The strip's figures wrapped at a narrow width take more than four lines; a tall window has
    // the room, so the strip gets it (a short window keeps it to four lines, to leave the view).
    const std::vector<std::string> entries = {
        "249.1 ms",          "4 fps",   "GPU 210.3 ms",        "place voxel", "material 12 (light)",
        "target 120 45 300", "unsaved", "walk: on the ground", "F1: keys"};
    auto chars = [](std::string_view s) {
        return static_cast<float>(s.size()) * 7.0f;
    };                        // 7 px per glyph
    const float pad = 16.0f;  // ImGui's window padding, both sides
    for (glm::vec2 window : {glm::vec2(200, 700), glm::vec2(240, 1000)}) {
        SCOPED_TRACE(testing::Message() << window.x << "x" << window.y);
        HudLayout l = game::layoutHud(window, kLine, false, true);
        ASSERT_TRUE(l.compact);
        const auto lines = game::wrapEntries(entries, ", ", l.stats.size.x - pad, chars);
        EXPECT_GT(lines.size(), 4u);
        EXPECT_GE(l.stats.size.y, float(lines.size()) * kLine + pad) << lines.size() << " lines";
        // And the view keeps most of the window.
        EXPECT_LE(l.stats.size.y, window.y * 0.5f);
    }
    HudLayout wide = game::layoutHud({320, 180}, kLine, false, false);
    EXPECT_LE(wide.stats.size.y, 4.0f * kLine + 16.0f);
}
