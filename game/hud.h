// The HUD (Dear ImGui, core API only): frame time and per-pass GPU milliseconds, emitters,
// bricks and memory, undo memory, lighting settings, the edit tool and material palette, the
// keys, a crosshair with an outline of the voxels the next edit touches, messages, and the
// unsaved-changes prompt. It reads a snapshot of the sandbox (HudStats), changes settings
// through HudControls, and reports button presses as HudActions. Where each panel goes, and
// how much it may take, comes from layoutHud (game/hud_layout.h): side by side, or one compact
// strip on small windows; text wraps between entries and long lists scroll.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "game/camera_controller.h"
#include "game/edit_tools.h"
#include "game/hud_layout.h"
#include "game/lighting_panel.h"
#include "game/undo_history.h"
#include "lighting/lighting_settings.h"
#include "render/dvf_sky/dvf_sky.h"
#include "render/gpu_world.h"
#include "render/irradiance_cache/irradiance_cache.h"
#include "shared/frame_params.h"
#include "world/scene.h"

namespace game {

struct HudStats {
    double cpuFrameMs = 0.0;
    std::vector<std::pair<std::string, double>> passMs;
    glm::uvec2 renderSize{0}, windowSize{0};
    std::uint64_t frame = 0;
    std::uint32_t liveBricks = 0;
    std::uint64_t emitters =
        0;  // lighting::EmitterList entries (exposed emissive voxels, brick lights)
    bool regirSampling = false;  // the candidates came from ReGIR's grid (regir or auto's choice)
    engine::world::GridMemory cpuMemory;
    engine::render::GpuWorldMemory gpuMemory;
    bool cacheUsed = false;
    engine::render::IrradianceCacheStats cache;
    bool skyUsed = false;                 // the DVF sky term (or its reference) was added
    std::uint32_t accumulatedFrames = 0;  // frames averaged into the image (--accumulate), 0: off
    engine::render::DvfSkyStats sky;
    UndoStats undo;
    std::string worldName, savePath;
    std::string store;      // the save's store: regions and size on disk (game/background_saver.h)
    std::string streaming;  // regions in memory against the budget (game/streamed_world.h); or ""
    bool unsaved = false;
    bool mouseLook = false;
    Pick target;
    std::optional<engine::world::Box> preview;
    shared::FrameParams view{};  // to project the outline and crosshair
    std::string message;         // latest status line, empty for none
    std::string movement;        // fly or walk, and the walk's state and collision cost
    std::string objectTool;      // the object tool's status while it is on (game/object_tools.h)
};

struct HudControls {
    EditTools& tools;
    const engine::world::Palette& palette;
    engine::world::SkyLight& sky;
    float& renderScale;
    bool& autoScale;
    float& exposure;
    engine::lighting::LightingSettings& lighting;
};

struct HudActions {
    bool save = false;
    bool quitSave = false;     // unsaved prompt: save, then quit
    bool quitDiscard = false;  // unsaved prompt: quit without saving
    bool quitCancel = false;
    bool undo = false, redo = false;
};

// The key list, shown in the HUD (and in README.md's "Playing" section).
const std::vector<std::pair<const char*, const char*>>& keyBindings();

class Hud {
public:
    bool visible = true;
    bool showKeys = false;

    // Builds this frame's HUD; call between ImGui::NewFrame and ImGui::Render.
    HudActions draw(const HudStats& stats, HudControls& controls, bool quitPrompt);

private:
    void drawCrosshair(const HudStats& stats);
    void drawCompact(const HudStats& stats, HudControls& controls, const HudRect& area);
    void drawStats(const HudStats& stats, HudControls& controls, HudActions& actions,
                   const HudRect& area);
    void drawTools(const HudStats& stats, HudControls& controls, const HudRect& area);
    void drawKeys(const HudRect& area, bool compact);
    void drawMessage(const std::string& message, const HudRect& area);

    LightingPanel mLightingPanel;
    engine::world::MaterialId mShownMaterial = 0;  // the palette scrolls to a newly chosen one
};

}  // namespace game
