// The capture's render loop, shared by a whole capture and by a job's task: plays the flythrough
// from a frame on — frames nobody asked for are history (the warm-up, or frames already done),
// rendered and not written — and for each frame asked for reads it back, counts its rays, writes
// its PNG (and EXR) atomically and hands it on with its CSV row.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "capture_csv.h"
#include "capture_options.h"
#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "render/renderer.h"
#include "world/flythrough.h"
#include "world/scene.h"

namespace engine::gpu {
class Context;
}

namespace vox {

// Everything a capture renders, resolved and checked from its options before any GPU work: a
// typo in a world, path or option costs nothing.
struct CaptureSetup {
    engine::world::Scene scene;
    std::filesystem::path pathFile;
    engine::world::Flythrough fly;  // its timeline bound to `scene`
    double fps = 30.0;
    std::uint32_t count = 0;            // frames of the path at fps
    std::uint32_t first = 0, last = 0;  // --frames, within 0..count-1
    glm::uvec2 size{0};                 // the frames' (--size)
    glm::uvec2 renderSize{0};           // the lighting's (--render-scale of size)
    engine::lighting::LightingSettings lighting;
};
engine::Result<CaptureSetup> prepareCapture(const CaptureOptions& o);

std::string framePng(std::uint32_t frame);  // "frame_00012.png"
std::string frameExr(std::uint32_t frame);

struct CapturedFrame {
    std::uint32_t index = 0;
    const engine::render::FrameImages& images;
    CaptureCsvRow& row;  // wall_ms so far: render, readback, counts and the frame's files
};

struct RenderRequest {
    std::uint32_t from = 0, to = 0;              // frames played, inclusive
    std::function<bool(std::uint32_t)> written;  // which of them are written and handed on
    std::filesystem::path dir;
    bool exr = false;
    float exposure = 1.0f;
    std::string progressLabel = "capture";
};

// Plays the frames; returns the seconds it took. The setup is used up (its timeline has run).
engine::Result<double> renderCapture(
    engine::gpu::Context& ctx, CaptureSetup& setup, const RenderRequest& request,
    const std::function<engine::Status(const CapturedFrame&)>& onFrame);

}  // namespace vox
