#include "game/hud.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <imgui.h>

namespace game {

namespace {

// Ctrl+click lets a slider take typed text: keep the value finite and within the slider's range
// (the lighting knobs' sliders go through the number check in lighting_panel.cpp).
bool checkedSlider(const char* label, float* value, float min, float max, const char* format,
                   ImGuiSliderFlags flags = ImGuiSliderFlags_None) {
    const float before = *value;
    const bool changed =
        ImGui::SliderFloat(label, value, min, max, format, flags | ImGuiSliderFlags_AlwaysClamp);
    if (std::isfinite(*value)) return changed;
    *value = before;
    return false;
}

// The tools' material in words: its name, "(light)" for an emitter; "none" in a world without
// materials (the palette holds only "empty"), where placing is refused.
std::string materialText(const engine::world::Palette& palette, engine::world::MaterialId id) {
    if (id == engine::world::kEmpty || id >= palette.size())
        return "none (the world has no materials)";
    const engine::world::Material& m = palette[id];
    return m.name + (m.emissive() ? " (light)" : "");
}

std::string megabytes(std::uint64_t bytes) {
    if (bytes < (1u << 20)) return fmt::format("{:.1f} KiB", double(bytes) / 1024.0);
    return fmt::format("{:.1f} MiB", double(bytes) / (1024.0 * 1024.0));
}

ImU32 toColor(glm::vec3 linear) {
    // Albedo is linear; the swapchain shows sRGB values.
    auto encode = [](float c) {
        c = std::clamp(c, 0.0f, 1.0f);
        return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    };
    return ImGui::ColorConvertFloat4ToU32(
        ImVec4(encode(linear.x), encode(linear.y), encode(linear.z), 1.0f));
}

// Projects a world point to HUD pixels with the renderer's camera (render/camera.h); false
// behind the camera.
bool project(const shared::FrameParams& f, glm::vec3 p, ImVec2 display, ImVec2& out) {
    glm::vec3 d = p - glm::vec3(f.cameraPosition);
    float z = glm::dot(d, glm::vec3(f.cameraForward));
    if (z <= 0.05f) return false;
    float tanHalf = f.cameraPosition.w, aspect = f.cameraForward.w;
    float x = glm::dot(d, glm::vec3(f.cameraRight)) / (z * tanHalf * aspect);
    float y = -glm::dot(d, glm::vec3(f.cameraUp)) / (z * tanHalf);
    out = ImVec2((x * 0.5f + 0.5f) * display.x, (y * 0.5f + 0.5f) * display.y);
    return true;
}

void drawBox(ImDrawList* dl, const shared::FrameParams& f, const engine::world::Box& box,
             ImVec2 display, ImU32 color) {
    glm::vec3 lo(box.min), hi(box.max);
    glm::vec3 corner[8];
    for (int i = 0; i < 8; ++i)
        corner[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    for (int a = 0; a < 8; ++a)
        for (int bit : {1, 2, 4}) {
            int b = a | bit;
            if (b == a) continue;
            ImVec2 pa, pb;
            if (project(f, corner[a], display, pa) && project(f, corner[b], display, pb))
                dl->AddLine(pa, pb, color, 1.5f);
        }
}

// Places the next window at `area` (anchored at its top-left, or top-right for `right`) and
// lets it auto-size up to the area; beyond that it scrolls.
void placeWindow(const HudRect& area, bool right = false) {
    ImVec2 pos = right ? ImVec2(area.max().x, area.min.y) : ImVec2(area.min.x, area.min.y);
    ImGui::SetNextWindowPos(pos, ImGuiCond_Always, ImVec2(right ? 1.0f : 0.0f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(area.size.x, area.size.y));
}

constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
    ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoCollapse;

// The text width a panel of `area` leaves: its padding and a vertical scrollbar taken off.
float textWidth(const HudRect& area) {
    const ImGuiStyle& style = ImGui::GetStyle();
    return std::max(ImGui::GetFontSize(),
                    area.size.x - 2.0f * style.WindowPadding.x - style.ScrollbarSize);
}

// One line per group of whole entries that fits `width`: a wrap never splits "name 1.25".
void textEntries(const std::vector<std::string>& entries, float width) {
    auto measure = [](std::string_view t) {
        return ImGui::CalcTextSize(t.data(), t.data() + t.size()).x;
    };
    for (const std::string& line : wrapEntries(entries, ", ", width, measure))
        ImGui::TextUnformatted(line.c_str());
}

std::string fps(double ms) { return fmt::format("{:.0f} fps", ms > 0 ? 1000.0 / ms : 0.0); }

double gpuTotal(const HudStats& stats) {
    double gpu = 0.0;
    for (const auto& [name, ms] : stats.passMs) gpu += ms;
    return gpu;
}

}  // namespace

const std::vector<std::pair<const char*, const char*>>& keyBindings() {
    static const std::vector<std::pair<const char*, const char*>> keys = {
        {"Mouse", "look around (click the world to capture the mouse)"},
        {"W A S D", "fly forward, left, back, right"},
        {"Q / E", "fly down / up"},
        {"Shift / Alt", "fast / slow"},
        {"F", "walk / fly: walking has gravity and collision"},
        {"Space or E / Q", "walk mode: jump / crouch (Shift runs)"},
        {"Left click", "apply the tool (box: press at one corner, release at the other)"},
        {"Right click", "remove with the current brush"},
        {"Middle click, I", "eyedropper: take the material under the crosshair"},
        {"1 / 2 / 3", "tool: place / remove / paint"},
        {"4",
         "object tool: left click places the model (M: next) or drags the selected one; right "
         "click or N selects"},
        {"Arrows, Home / End", "object: move along X and Z, up / down (Shift: 8 voxels)"},
        {"R / Shift+R, [ / ]", "object: turn 90 degrees / 5 degrees about Y"},
        {"K, L, Backspace", "object: key at the current time, loop on/off, clear the path"},
        {"Delete", "object: delete"},
        {"B", "brush: voxel, box, sphere"},
        {"- / =", "sphere radius"},
        {"Wheel, , / .", "previous / next material"},
        {"Ctrl+Z / Ctrl+Y", "undo / redo (Ctrl+Shift+Z also redoes)"},
        {"Ctrl+S", "save (autosaves go to a separate file)"},
        {"F12 / Shift+F12", "screenshot: window / rendered image"},
        {"PageUp / PageDown", "render resolution up / down"},
        {"C", "next camera preset"},
        {"Tab / F1", "hide the HUD / the key list"},
        {"Esc", "release the mouse; again to quit"},
    };
    return keys;
}

HudActions Hud::draw(const HudStats& stats, HudControls& controls, bool quitPrompt) {
    HudActions actions;
    ImGuiIO& io = ImGui::GetIO();
    const ImGuiStyle& style = ImGui::GetStyle();
    const float line = ImGui::GetFont()->FontSize + style.ItemSpacing.y;  // at font scale 1
    HudLayout layout = layoutHud({io.DisplaySize.x, io.DisplaySize.y}, line, visible && showKeys,
                                 !stats.message.empty());
    io.FontGlobalScale = layout.fontScale;  // takes effect from the next frame
    drawCrosshair(stats);
    if (visible) {
        if (layout.compact) {
            drawCompact(stats, controls, layout.stats);
        } else {
            drawStats(stats, controls, actions, layout.stats);
            drawTools(stats, controls, layout.tools);
        }
        if (showKeys) drawKeys(layout.keys, layout.compact);
    }
    if (!stats.message.empty()) drawMessage(stats.message, layout.message);
    if (quitPrompt) {
        ImGui::OpenPopup("Unsaved changes");
        ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                                ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::SetNextWindowSizeConstraints(
            ImVec2(0, 0), ImVec2(io.DisplaySize.x - 8.0f, io.DisplaySize.y - 8.0f));
        if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::Text("%s has unsaved changes.", stats.worldName.c_str());
            // Side by side when they fit, else one under another.
            const char* labels[] = {"Save and quit (Y)", "Quit without saving (N)", "Cancel (Esc)"};
            float row = 0.0f;
            for (const char* label : labels)
                row += ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x +
                       style.ItemSpacing.x;
            bool sideBySide = row + 2.0f * style.WindowPadding.x <= io.DisplaySize.x - 8.0f;
            bool* results[] = {&actions.quitSave, &actions.quitDiscard, &actions.quitCancel};
            for (int i = 0; i < 3; ++i) {
                if (i > 0 && sideBySide) ImGui::SameLine();
                if (ImGui::Button(labels[i])) *results[i] = true;
            }
            ImGui::EndPopup();
        }
    }
    return actions;
}

void Hud::drawMessage(const std::string& message, const HudRect& area) {
    // Centred at the bottom, as wide as the text up to the window; wraps to a second line.
    ImGui::SetNextWindowPos(ImVec2(area.min.x + area.size.x * 0.5f, area.max().y), ImGuiCond_Always,
                            ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(area.size.x, area.size.y));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("##message", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing |
                     ImGuiWindowFlags_NoNav);
    ImGui::PushTextWrapPos(textWidth(area) + ImGui::GetStyle().WindowPadding.x);
    ImGui::TextUnformatted(message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void Hud::drawCrosshair(const HudStats& stats) {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    ImVec2 display = ImGui::GetIO().DisplaySize;
    ImVec2 c(display.x * 0.5f, display.y * 0.5f);
    ImU32 shadow = IM_COL32(0, 0, 0, 160), white = IM_COL32(255, 255, 255, 230);
    for (auto [color, width] : {std::pair{shadow, 3.0f}, std::pair{white, 1.0f}}) {
        dl->AddLine(ImVec2(c.x - 8, c.y), ImVec2(c.x + 9, c.y), color, width);
        dl->AddLine(ImVec2(c.x, c.y - 8), ImVec2(c.x, c.y + 9), color, width);
    }
    if (stats.preview && stats.mouseLook)
        drawBox(dl, stats.view, *stats.preview, display, IM_COL32(255, 230, 80, 220));
}

void Hud::drawCompact(const HudStats& stats, HudControls& controls, const HudRect& area) {
    // Small windows: the figures a player needs, wrapped between entries; the keys still work.
    placeWindow(area);
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("##compact", nullptr, ImGuiWindowFlags_NoDecoration | kPanelFlags);
    const EditTools& t = controls.tools;
    std::vector<std::string> entries = {
        fmt::format("{:.1f} ms", stats.cpuFrameMs),
        fps(stats.cpuFrameMs),
        fmt::format("GPU {:.1f} ms", gpuTotal(stats)),
        fmt::format("{} {}", toolName(t.tool), brushName(t.brush)),
        materialText(controls.palette, t.material),
    };
    if (!stats.objectTool
             .empty()) {  // the object tool instead, one entry per "; " part to wrap between
        entries.erase(entries.begin() + 3);
        std::size_t at = 3;
        for (std::size_t from = 0; from <= stats.objectTool.size();) {
            std::size_t end = std::min(stats.objectTool.find("; ", from), stats.objectTool.size());
            entries.insert(entries.begin() + std::ptrdiff_t(at++),
                           stats.objectTool.substr(from, end - from));
            from = end + 2;
        }
    }
    if (stats.target.hit)
        entries.push_back(fmt::format("target {} {} {}", stats.target.voxel.x, stats.target.voxel.y,
                                      stats.target.voxel.z));
    if (stats.unsaved) entries.push_back("unsaved");
    if (!stats.movement.empty()) entries.push_back(stats.movement);
    entries.push_back(showKeys ? "F1: hide keys" : "F1: keys");
    // Only whole lines: the strip has no scrollbar, so what does not fit is left out.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float lineHeight = ImGui::GetTextLineHeightWithSpacing();
    const auto fit = static_cast<std::size_t>(std::max(
        1.0f, std::floor((area.size.y - 2.0f * style.WindowPadding.y + style.ItemSpacing.y) /
                         lineHeight)));
    auto measure = [](std::string_view text) {
        return ImGui::CalcTextSize(text.data(), text.data() + text.size()).x;
    };
    auto lines = wrapEntries(entries, ", ", textWidth(area), measure);
    for (std::size_t i = 0; i < std::min(fit, lines.size()); ++i)
        ImGui::TextUnformatted(lines[i].c_str());
    ImGui::End();
}

void Hud::drawStats(const HudStats& stats, HudControls& controls, HudActions& actions,
                    const HudRect& area) {
    placeWindow(area);
    ImGui::SetNextWindowBgAlpha(0.65f);
    ImGui::Begin("Frame", nullptr, kPanelFlags);
    const float width = textWidth(area);
    textEntries({fmt::format("frame {:.1f} ms", stats.cpuFrameMs), fps(stats.cpuFrameMs),
                 fmt::format("GPU {:.2f} ms", gpuTotal(stats))},
                width);
    std::vector<std::string> passes;
    for (const auto& [name, ms] : stats.passMs)
        passes.push_back(fmt::format("{} {:.2f}", name, ms));
    textEntries(passes, width);
    if (!stats.movement.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
        ImGui::TextUnformatted(stats.movement.c_str());
        ImGui::PopTextWrapPos();
    }
    textEntries({fmt::format("render {}x{}", stats.renderSize.x, stats.renderSize.y),
                 fmt::format("window {}x{}", stats.windowSize.x, stats.windowSize.y)},
                width);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    checkedSlider("render scale", &controls.renderScale, 1.0f / 16.0f, 1.0f, "%.3f");
    ImGui::SameLine();
    ImGui::Checkbox("auto", &controls.autoScale);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("adapt the render scale to keep the frame responsive");
    textEntries(
        {fmt::format("bricks {}", stats.liveBricks),
         fmt::format("emitters {}{}", stats.emitters, stats.regirSampling ? " (regir)" : "")},
        width);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "emissive voxels with an exposed face; a cell all of one emissive material is one "
            "brick light; (regir): candidates from ReGIR's grid (--sampling regir, or auto's "
            "choice for many lights spread far apart)");
    textEntries(
        {"memory CPU " + megabytes(stats.cpuMemory.topGridBytes + stats.cpuMemory.brickPoolBytes),
         "GPU " + megabytes(stats.gpuMemory.topGridBytes + stats.gpuMemory.brickPageBytes +
                            stats.gpuMemory.pageTableBytes + stats.gpuMemory.paletteBytes)},
        width);
    if (stats.cacheUsed) {
        textEntries({"irradiance cache " + megabytes(stats.cache.bytes),
                     fmt::format("{} entries", stats.cache.entries)},
                    width);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "entries of voxels the camera has seen, least recently seen evicted at the memory "
                "budget");
        textEntries(
            {fmt::format("cache updates {} ({} waiting)", stats.cache.updated, stats.cache.waiting),
             fmt::format("{:.0f}k rays", static_cast<double>(stats.cache.raysTraced) / 1000.0)},
            width);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "entries updated this frame within the ray budget (--cache-budget); waiting: "
                "visible ones left for later frames");
    }
    if (stats.skyUsed) {
        textEntries(
            {fmt::format("sky masks {} ({} waiting)", stats.sky.usedSlots, stats.sky.queued),
             fmt::format("{} traced, {:.0f}k rays", stats.sky.tracedMasks,
                         static_cast<double>(stats.sky.tracedRays) / 1000.0)},
            width);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "DVF sky light: visibility masks per 8^3 cell and face the camera has seen; an "
                "edit re-traces only the directions through it");
    }
    if (stats.accumulatedFrames > 0) {
        ImGui::Text("accumulated %u still frames", stats.accumulatedFrames);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "the image is the mean of the frames since the camera, world, lights or sky last "
                "changed");
    }
    textEntries(
        {fmt::format("undo {} / redo {} steps", stats.undo.undoSteps, stats.undo.redoSteps),
         fmt::format("{} of {}", megabytes(stats.undo.bytes), megabytes(stats.undo.maxBytes))},
        width);
    if (stats.undo.droppedSteps)
        ImGui::Text("  %zu oldest steps dropped (budget)", stats.undo.droppedSteps);
    if (!showKeys) ImGui::TextDisabled("F1: keys, Tab: hide HUD");
    if (ImGui::Button("Undo")) actions.undo = true;
    ImGui::SameLine();
    if (ImGui::Button("Redo")) actions.redo = true;
    ImGui::SameLine();
    if (ImGui::Button("Save")) actions.save = true;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::Text("%s%s", stats.savePath.c_str(), stats.unsaved ? " (unsaved changes)" : "");
    ImGui::TextUnformatted(stats.store.c_str());
    if (!stats.streaming.empty()) ImGui::TextUnformatted(stats.streaming.c_str());
    ImGui::PopTextWrapPos();
    engine::lighting::LightingSettings& l = controls.lighting;
    if (!ImGui::CollapsingHeader(
            fmt::format("Lighting: {}###lighting", engine::lighting::methodName(l.method))
                .c_str())) {
        ImGui::End();
        return;
    }
    mLightingPanel.draw(l, width);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    checkedSlider("exposure", &controls.exposure, 0.05f, 8.0f, "%.2f",
                  ImGuiSliderFlags_Logarithmic);
    glm::vec3 d = controls.sky.sunDirection;
    float elevation = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
    float azimuth = glm::degrees(std::atan2(d.x, d.z));
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    bool changed = checkedSlider("sun elevation", &elevation, -10.0f, 90.0f, "%.0f deg");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    changed |= checkedSlider("sun azimuth", &azimuth, -180.0f, 180.0f, "%.0f deg");
    if (changed) {
        float e = glm::radians(elevation), a = glm::radians(azimuth);
        controls.sky.sunDirection = {std::cos(e) * std::sin(a), std::sin(e),
                                     std::cos(e) * std::cos(a)};
    }
    ImGui::End();
}

void Hud::drawTools(const HudStats& stats, HudControls& controls, const HudRect& area) {
    placeWindow(area, /*right=*/true);
    ImGui::SetNextWindowBgAlpha(0.65f);
    ImGui::Begin("Edit", nullptr, kPanelFlags);
    const ImGuiStyle& style = ImGui::GetStyle();
    EditTools& t = controls.tools;
    int tool = static_cast<int>(t.tool);
    ImGui::RadioButton("place", &tool, 0);
    ImGui::SameLine();
    ImGui::RadioButton("remove", &tool, 1);
    ImGui::SameLine();
    ImGui::RadioButton("paint", &tool, 2);
    t.tool = static_cast<Tool>(tool);
    if (!stats.objectTool.empty())
        ImGui::TextWrapped("%s (1-3: back to voxels)", stats.objectTool.c_str());
    int brush = static_cast<int>(t.brush);
    ImGui::RadioButton("voxel", &brush, 0);
    ImGui::SameLine();
    ImGui::RadioButton("box", &brush, 1);
    ImGui::SameLine();
    ImGui::RadioButton("sphere", &brush, 2);
    if (brush != static_cast<int>(t.brush)) t.cancelDrag();
    t.brush = static_cast<Brush>(brush);
    if (t.brush == Brush::Sphere) {
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
        checkedSlider("radius", &t.radius, 0.5f, 32.0f, "%.1f");
    }

    // The palette: emissive materials (lights) get a bright frame and a star. It scrolls in a
    // box that leaves room for the lines below it (material, target, drag hint).
    const auto& materials = controls.palette.materials();
    const float swatch = ImGui::GetFrameHeight();
    const float cell = swatch + style.ItemSpacing.x;
    const float below = 3.0f * ImGui::GetTextLineHeightWithSpacing() + style.WindowPadding.y;
    const float room = area.max().y - ImGui::GetCursorScreenPos().y - below;
    const int count = static_cast<int>(materials.size()) - 1;  // id 0 is empty
    PaletteGrid grid = paletteGrid(count, textWidth(area), room, cell);
    const float boxWidth = grid.columns * cell + (grid.scrolls() ? style.ScrollbarSize : 0.0f);
    ImGui::BeginChild("palette", ImVec2(boxWidth, grid.visibleRows * cell), false);
    for (std::size_t i = 1; i < materials.size(); ++i) {
        const auto& m = materials[i];
        ImGui::PushID(static_cast<int>(i));
        glm::vec3 shown = m.emissive() ? glm::min(m.emittedRadiance(), glm::vec3(1.0f)) : m.albedo;
        ImVec4 col = ImGui::ColorConvertU32ToFloat4(toColor(shown));
        bool selected = t.material == i;
        if (selected || m.emissive()) {
            ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, selected ? 2.0f : 1.0f);
            ImGui::PushStyleColor(ImGuiCol_Border,
                                  selected ? ImVec4(1, 1, 1, 1) : ImVec4(1.0f, 0.85f, 0.3f, 1.0f));
        }
        if (ImGui::ColorButton(m.name.c_str(), col, ImGuiColorEditFlags_NoTooltip,
                               ImVec2(swatch, swatch)))
            t.material = static_cast<engine::world::MaterialId>(i);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "%s%s", m.name.c_str(),
                m.emissive() ? fmt::format(" (light, {:.1f})", m.emissionStrength).c_str() : "");
        if (selected && mShownMaterial != t.material) {
            ImGui::SetScrollHereY(0.5f);  // a material chosen by key or wheel comes into view
            mShownMaterial = t.material;
        }
        if (selected || m.emissive()) {
            ImGui::PopStyleColor();
            ImGui::PopStyleVar();
        }
        ImGui::PopID();
        if (i % static_cast<std::size_t>(grid.columns) != 0 && i + 1 < materials.size())
            ImGui::SameLine();
    }
    ImGui::EndChild();
    const float width = textWidth(area);
    textEntries({"material: " + materialText(controls.palette, t.material)}, width);
    if (stats.target.hit) {
        const auto& hit = controls.palette[stats.target.material];
        textEntries({fmt::format("target ({}, {}, {}) {}", stats.target.voxel.x,
                                 stats.target.voxel.y, stats.target.voxel.z, hit.name),
                     fmt::format("{:.1f} away", stats.target.distance)},
                    width);
    } else {
        ImGui::TextUnformatted("target: sky");
    }
    if (t.dragging()) textEntries({"box: release to apply", "Esc to cancel"}, width);
    ImGui::End();
}

void Hud::drawKeys(const HudRect& area, bool compact) {
    placeWindow(area);
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("Keys (F1)", nullptr, kPanelFlags | (compact ? ImGuiWindowFlags_NoTitleBar : 0));
    // The description column wraps to what is left of the panel; the list scrolls.
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit,
                          ImVec2(textWidth(area), 0.0f))) {
        ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
        for (const auto& [key, what] : keyBindings()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(key);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", what);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace game
