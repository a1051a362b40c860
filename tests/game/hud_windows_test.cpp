// The real HUD (game/hud.h) drawn by Dear ImGui without a window or GPU: after a few frames to
// let the auto-sized windows settle, every HUD window lies inside the display and no two
// overlap, at 320x180, 640x360, 1280x720 and 3840x2160, with the irradiance cache's long pass
// list, the lighting settings open, a status message, the key list and 300 materials.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "game/hud.h"

namespace {

struct Rect {
    std::string name;
    ImVec2 min, max;
};

class HudWindows : public testing::Test {
protected:
    void SetUp() override {
        ImGui::CreateContext();
        unsigned char* pixels;
        int w, h;
        ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // a headless atlas
        ImGui::GetIO().IniFilename = nullptr;
        for (int i = 0; i < 300; ++i) {
            engine::world::Material m;
            m.name = "material " + std::to_string(i);
            m.albedo = glm::vec3(float(i % 7) / 7.0f, float(i % 5) / 5.0f, float(i % 3) / 3.0f);
            palette.add(m);
        }
        stats.passMs = {{"upload", 0.10},
                        {"primary_rays", 4.22},
                        {"restir_initial", 17.82},
                        {"restir_temporal", 3.41},
                        {"restir_spatial", 5.88},
                        {"restir_shade", 13.50},
                        {"cache.trace_static", 11.24},
                        {"cache.visibility_static", 2.21},
                        {"cache.visibility_dynamic", 36.76},
                        {"cache.bounce", 136.04},
                        {"cache.filter", 2.11},
                        {"cache.gather", 2.90},
                        {"tonemap", 0.34},
                        {"present", 4.34}};
        stats.cpuFrameMs = 249.1;
        stats.cacheUsed = true;
        stats.cache.entries = 6127;
        stats.savePath = "saves/a_world_with_a_long_name.toml";
        stats.unsaved = true;
        stats.target.hit = true;
        stats.message =
            "screenshot hud_rendered_640x360.png (160x90, rendered image), a message long enough "
            "to wrap";
    }
    void TearDown() override { ImGui::DestroyContext(); }

    // Draws a few frames at `size`; the rectangles of the HUD windows drawn in the last one.
    std::vector<Rect> drawAt(ImVec2 size) {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = size;
        io.DeltaTime = 1.0f / 60.0f;
        std::vector<Rect> rects;
        for (int frame = 0; frame < 4; ++frame) {
            ImGui::NewFrame();
            game::HudControls controls{tools,     palette,  sky,     renderScale,
                                       autoScale, exposure, lighting};
            hud.draw(stats, controls, false);
            ImGui::Render();
            // Open the lighting settings (the tallest part of the stats panel), as a click would.
            if (ImGuiWindow* w = ImGui::FindWindowByName("Frame"))
                w->StateStorage.SetInt(w->GetID("###lighting"), 1);
        }
        for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
            if (w->WasActive && !(w->Flags & ImGuiWindowFlags_ChildWindow) &&
                !(w->Flags & ImGuiWindowFlags_Tooltip) && std::string(w->Name) != "Debug##Default")
                rects.push_back(
                    {w->Name, w->Pos, ImVec2(w->Pos.x + w->Size.x, w->Pos.y + w->Size.y)});
        return rects;
    }

    void expectApartAndInside(ImVec2 size) {
        auto rects = drawAt(size);
        EXPECT_GE(rects.size(), 2u);
        for (std::size_t i = 0; i < rects.size(); ++i) {
            const Rect& a = rects[i];
            EXPECT_TRUE(a.min.x >= 0 && a.min.y >= 0 && a.max.x <= size.x && a.max.y <= size.y)
                << a.name << " at " << a.min.x << "," << a.min.y << " .. " << a.max.x << ","
                << a.max.y;
            for (std::size_t j = i + 1; j < rects.size(); ++j) {
                const Rect& b = rects[j];
                bool overlap = a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y &&
                               b.min.y < a.max.y;
                EXPECT_FALSE(overlap) << a.name << " and " << b.name;
            }
        }
    }

    game::Hud hud;
    game::HudStats stats;
    game::EditTools tools;
    engine::world::Palette palette;
    engine::world::SkyLight sky;
    float renderScale = 0.25f, exposure = 1.0f;
    bool autoScale = false;
    engine::lighting::LightingSettings lighting;
};

}  // namespace

TEST_F(HudWindows, ApartAndInsideAtEverySize) {
    for (bool keys : {false, true}) {
        hud.showKeys = keys;
        for (ImVec2 size : {ImVec2(320, 180), ImVec2(200, 700), ImVec2(640, 360), ImVec2(1280, 720),
                            ImVec2(3840, 2160)}) {
            SCOPED_TRACE(testing::Message()
                         << size.x << "x" << size.y << (keys ? " with keys" : ""));
            expectApartAndInside(size);
        }
    }
}

TEST_F(HudWindows, AWorldWithNoMaterialsDraws) {
    // A scene of [world] alone, or a .vox without colours: the palette holds only "empty", and
    // the tools' material (1 by default) names nothing. The HUD says so instead of aborting.
    palette = engine::world::Palette();
    stats.target.hit = false;
    for (bool keys : {false, true}) {
        hud.showKeys = keys;
        for (ImVec2 size : {ImVec2(320, 180), ImVec2(1280, 720)}) {
            SCOPED_TRACE(testing::Message()
                         << size.x << "x" << size.y << (keys ? " with keys" : ""));
            EXPECT_NO_THROW(expectApartAndInside(size));
        }
    }
}
