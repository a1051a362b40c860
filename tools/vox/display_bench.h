// vox bench display's parts (bench_display_command.cpp has the story): the rows it compares,
// how a row renders and what it shows at the display's size, the converged reference of a frame,
// and the stability cases (display_stability.cpp).
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "render/renderer.h"
#include "world/flythrough.h"
#include "world/scene.h"

namespace engine::gpu {
class Context;
}

namespace vox {

// One way of showing the frame: a display mode at a render scale of the display's size.
struct DisplayRow {
    engine::lighting::Display mode = engine::lighting::Display::Raw;
    double scale = 1.0;
    std::string label() const;  // "denoised 0.5", "raw 1"
};

// raw, upsampled and denoised at each scale, then raw at the display's own size.
std::vector<DisplayRow> displayRows(const std::vector<double>& scales);

// The row's frame: the render size is the display's times the scale (rounded, as vox render
// --render-scale does); a raw row's display is its render size.
engine::render::FrameSettings rowFrame(const DisplayRow& row, glm::uvec2 display);
engine::lighting::LightingSettings rowLighting(const DisplayRow& row,
                                               engine::lighting::LightingSettings base);

// What the row shows after its last render, linear, at the display's size: a raw image smaller
// than the display blown up by nearest neighbour, as the presenter's blit does.
std::vector<glm::vec4> shownImage(engine::render::Renderer& renderer, glm::uvec2 display);

// A linear image as a PNG for the eye: scaled by `exposure`, x / (1 + x) per channel, sRGB.
engine::Status writeViewPng(const std::filesystem::path& path, const std::vector<glm::vec4>& image,
                            glm::uvec2 size, float exposure);
// The exposure that puts the reference's mean luminance at 0.18 (the middle grey).
float viewExposure(const std::vector<glm::vec4>& reference);

// The converged image of a frame at the display's size: the path tracer with the rows' lighting
// model (their indirect term's bounces; none: direct light only), box-filtered over each pixel,
// `spp` samples.
class DisplayReference {
public:
    DisplayReference(engine::gpu::Context& ctx, const engine::lighting::LightingSettings& lighting,
                     std::uint32_t spp);
    std::vector<glm::vec4> render(engine::world::Scene& scene,
                                  const engine::world::CameraPreset& camera, glm::uvec2 display,
                                  double timeSeconds);

private:
    std::unique_ptr<engine::render::Renderer> mRenderer;
    engine::lighting::LightingSettings mLighting;
    std::uint32_t mSpp;
};

// The stability cases on one world with a timeline: for each event, a still camera (the path's at
// that moment) converged, the event, frames until the changed region is back within 10 % of its
// new steady value; a moving object's ghost trail; still-camera flicker and error. Adds markdown
// rows to `table` and one CSV line per (case, row) to `csv`.
struct StabilityOptions {
    glm::uvec2 display{320, 180};
    std::uint32_t referenceSpp = 64;
    std::uint32_t stillFrames = 32;  // frames before each event
    std::uint32_t afterFrames = 12;  // frames after it
    std::uint32_t ghostFrames = 16;  // frames of a moving object
    std::uint32_t cases = 0;         // the first this many cases (0: all)
    // Not empty: each still camera's last frame per row, its reference and a heat map of their
    // difference as PNGs here, and the error split (edges, low frequencies, the reference's own
    // noise against a reference of 4x the samples) in the CSV.
    std::filesystem::path images;
};
engine::Status displayStability(engine::gpu::Context& ctx, const engine::world::Scene& scene,
                                const engine::world::Flythrough& fly,
                                const std::vector<DisplayRow>& rows,
                                const engine::lighting::LightingSettings& base,
                                const StabilityOptions& o, std::string& table, std::ostream& csv);

}  // namespace vox
