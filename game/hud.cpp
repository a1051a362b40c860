#include "game/hud.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <imgui.h>

namespace game {

namespace {

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
    return ImGui::ColorConvertFloat4ToU32(ImVec4(encode(linear.x), encode(linear.y), encode(linear.z), 1.0f));
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

void drawBox(ImDrawList* dl, const shared::FrameParams& f, const engine::world::Box& box, ImVec2 display, ImU32 color) {
    glm::vec3 lo(box.min), hi(box.max);
    glm::vec3 corner[8];
    for (int i = 0; i < 8; ++i) corner[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    for (int a = 0; a < 8; ++a)
        for (int bit : {1, 2, 4}) {
            int b = a | bit;
            if (b == a) continue;
            ImVec2 pa, pb;
            if (project(f, corner[a], display, pa) && project(f, corner[b], display, pb)) dl->AddLine(pa, pb, color, 1.5f);
        }
}

}  // namespace

const std::vector<std::pair<const char*, const char*>>& keyBindings() {
    static const std::vector<std::pair<const char*, const char*>> keys = {
        {"Mouse", "look around (click the world to capture the mouse)"},
        {"W A S D", "fly forward, left, back, right"},
        {"Q / E", "fly down / up"},
        {"Shift / Alt", "fast / slow"},
        {"Left click", "apply the tool (box: press at one corner, release at the other)"},
        {"Right click", "remove with the current brush"},
        {"Middle click, I", "eyedropper: take the material under the crosshair"},
        {"1 / 2 / 3", "tool: place / remove / paint"},
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
    drawCrosshair(stats);
    if (visible) {
        drawStats(stats, controls, actions);
        drawTools(stats, controls);
        if (showKeys) drawKeys();
    }
    if (!stats.message.empty()) {
        ImGuiIO& io = ImGui::GetIO();
        ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y - 8.0f), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
        ImGui::SetNextWindowBgAlpha(0.6f);
        ImGui::Begin("##message", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                         ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
        ImGui::TextUnformatted(stats.message.c_str());
        ImGui::End();
    }
    if (quitPrompt) {
        ImGui::OpenPopup("Unsaved changes");
        ImGuiIO& io = ImGui::GetIO();
        ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::Text("%s has unsaved changes.", stats.worldName.c_str());
            if (ImGui::Button("Save and quit (Y)")) actions.quitSave = true;
            ImGui::SameLine();
            if (ImGui::Button("Quit without saving (N)")) actions.quitDiscard = true;
            ImGui::SameLine();
            if (ImGui::Button("Cancel (Esc)")) actions.quitCancel = true;
            ImGui::EndPopup();
        }
    }
    return actions;
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
    if (stats.preview && stats.mouseLook) drawBox(dl, stats.view, *stats.preview, display, IM_COL32(255, 230, 80, 220));
}

void Hud::drawStats(const HudStats& stats, HudControls& controls, HudActions& actions) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.65f);
    ImGui::Begin("Frame", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing);
    double gpu = 0.0;
    for (const auto& [name, ms] : stats.passMs) gpu += ms;
    ImGui::Text("frame %.1f ms (%.0f fps), GPU %.2f ms", stats.cpuFrameMs, stats.cpuFrameMs > 0 ? 1000.0 / stats.cpuFrameMs : 0.0,
                gpu);
    std::string passes;
    for (const auto& [name, ms] : stats.passMs) passes += fmt::format("{}{} {:.2f}", passes.empty() ? "" : ", ", name, ms);
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
    ImGui::TextUnformatted(passes.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Text("render %ux%u -> window %ux%u", stats.renderSize.x, stats.renderSize.y, stats.windowSize.x,
                stats.windowSize.y);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::SliderFloat("render scale", &controls.renderScale, 1.0f / 16.0f, 1.0f, "%.3f");
    ImGui::SameLine();
    ImGui::Checkbox("auto", &controls.autoScale);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("adapt the render scale to keep the frame responsive");
    ImGui::Text("bricks %u, emitters %llu", stats.liveBricks, static_cast<unsigned long long>(stats.emitters));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("emissive voxels with an exposed face; a cell all of one emissive material is one brick light");
    ImGui::Text("memory CPU %s, GPU %s", megabytes(stats.cpuMemory.topGridBytes + stats.cpuMemory.brickPoolBytes).c_str(),
                megabytes(stats.gpuMemory.topGridBytes + stats.gpuMemory.brickPageBytes + stats.gpuMemory.pageTableBytes +
                          stats.gpuMemory.paletteBytes)
                    .c_str());
    if (stats.cacheUsed) {
        ImGui::Text("irradiance cache %s, %u entries", megabytes(stats.cache.bytes).c_str(), stats.cache.entries);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("entries of voxels the camera has seen, least recently seen evicted at the memory budget");
        ImGui::Text("cache updates %u (%u waiting), %.0fk rays", stats.cache.updated, stats.cache.waiting,
                    static_cast<double>(stats.cache.raysTraced) / 1000.0);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("entries updated this frame within the ray budget (--cache-budget); waiting: visible ones left for later frames");
    }
    ImGui::Text("undo %zu / redo %zu steps, %s of %s", stats.undo.undoSteps, stats.undo.redoSteps,
                megabytes(stats.undo.bytes).c_str(), megabytes(stats.undo.maxBytes).c_str());
    if (stats.undo.droppedSteps) ImGui::Text("  %zu oldest steps dropped (budget)", stats.undo.droppedSteps);
    if (!showKeys) ImGui::TextDisabled("F1: keys, Tab: hide HUD");
    if (ImGui::Button("Undo")) actions.undo = true;
    ImGui::SameLine();
    if (ImGui::Button("Redo")) actions.redo = true;
    ImGui::SameLine();
    if (ImGui::Button("Save")) actions.save = true;
    ImGui::Text("%s%s", stats.savePath.c_str(), stats.unsaved ? " (unsaved changes)" : "");
    engine::lighting::LightingSettings& l = controls.lighting;
    if (!ImGui::CollapsingHeader(fmt::format("Lighting: {}###lighting", engine::lighting::methodName(l.method)).c_str())) {
        ImGui::End();
        return;
    }
    mLightingPanel.draw(l);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::SliderFloat("exposure", &controls.exposure, 0.05f, 8.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    glm::vec3 d = controls.sky.sunDirection;
    float elevation = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
    float azimuth = glm::degrees(std::atan2(d.x, d.z));
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    bool changed = ImGui::SliderFloat("sun elevation", &elevation, -10.0f, 90.0f, "%.0f deg");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    changed |= ImGui::SliderFloat("sun azimuth", &azimuth, -180.0f, 180.0f, "%.0f deg");
    if (changed) {
        float e = glm::radians(elevation), a = glm::radians(azimuth);
        controls.sky.sunDirection = {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
    }
    ImGui::End();
}

void Hud::drawTools(const HudStats& stats, HudControls& controls) {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 8, 8), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.65f);
    ImGui::Begin("Edit", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing);
    EditTools& t = controls.tools;
    int tool = static_cast<int>(t.tool);
    ImGui::RadioButton("place", &tool, 0);
    ImGui::SameLine();
    ImGui::RadioButton("remove", &tool, 1);
    ImGui::SameLine();
    ImGui::RadioButton("paint", &tool, 2);
    t.tool = static_cast<Tool>(tool);
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
        ImGui::SliderFloat("radius", &t.radius, 0.5f, 32.0f, "%.1f");
    }

    // The palette: emissive materials (lights) get a bright frame and a star.
    const auto& materials = controls.palette.materials();
    const float swatch = ImGui::GetFrameHeight();
    for (std::size_t i = 1; i < materials.size(); ++i) {
        const auto& m = materials[i];
        ImGui::PushID(static_cast<int>(i));
        glm::vec3 shown = m.emissive() ? glm::min(m.emittedRadiance(), glm::vec3(1.0f)) : m.albedo;
        ImVec4 col = ImGui::ColorConvertU32ToFloat4(toColor(shown));
        bool selected = t.material == i;
        if (selected || m.emissive()) {
            ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, selected ? 2.0f : 1.0f);
            ImGui::PushStyleColor(ImGuiCol_Border, selected ? ImVec4(1, 1, 1, 1) : ImVec4(1.0f, 0.85f, 0.3f, 1.0f));
        }
        if (ImGui::ColorButton(m.name.c_str(), col, ImGuiColorEditFlags_NoTooltip, ImVec2(swatch, swatch)))
            t.material = static_cast<engine::world::MaterialId>(i);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s%s", m.name.c_str(), m.emissive() ? fmt::format(" (light, {:.1f})", m.emissionStrength).c_str() : "");
        if (selected || m.emissive()) {
            ImGui::PopStyleColor();
            ImGui::PopStyleVar();
        }
        ImGui::PopID();
        if (i % 8 != 0 && i + 1 < materials.size()) ImGui::SameLine();
    }
    const auto& cur = controls.palette[t.material];
    ImGui::Text("material: %s%s", cur.name.c_str(), cur.emissive() ? " (light)" : "");
    if (stats.target.hit) {
        const auto& hit = controls.palette[stats.target.material];
        ImGui::Text("target (%d, %d, %d) %s, %.1f away", stats.target.voxel.x, stats.target.voxel.y, stats.target.voxel.z,
                    hit.name.c_str(), stats.target.distance);
    } else {
        ImGui::TextUnformatted("target: sky");
    }
    if (t.dragging()) ImGui::TextUnformatted("box: release to apply, Esc to cancel");
    ImGui::End();
}

void Hud::drawKeys() {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(8, io.DisplaySize.y - 8), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("Keys (F1)", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing);
    if (ImGui::BeginTable("keys", 2)) {
        for (const auto& [key, what] : keyBindings()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(key);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(what);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace game
