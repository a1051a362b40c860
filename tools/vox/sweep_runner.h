// Measuring lighting settings against a reference: the shared machinery of `vox bench accuracy`,
// `vox bench sweep` and `vox bench recommend`. One point = one scene, view and setting, its
// median per-pass GPU time and its error against the converged reference, from the same run.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "render/camera.h"
#include "world/scene.h"

namespace engine::gpu {
class Context;
}
namespace engine::render {
class Renderer;
}

namespace vox {

struct SweepPoint {
    std::string scene;
    std::string label;
    std::string method;
    std::map<std::string, double> passMs;  // median per pass over the measured frames
    double totalMs = 0.0;                  // median frame time, upload excluded
    double fastestMs =
        0.0;  // the fastest measured frame: the least slowed by other work on a shared machine
    // Median CPU time of this process per frame (rendering only, readback excluded). On a CPU
    // device (lavapipe) that is the device's work plus the host's, and other processes taking the
    // cores do not lengthen it as they lengthen the GPU timestamps.
    double cpuMs = 0.0;
    // Median wall time of the whole Renderer::render call per frame: host work, submission and the
    // wait for the device (readback excluded); what a player waits, other processes' load included.
    double wallMs = 0.0;
    double mae = 0.0, mse = 0.0, rmae = 0.0;
    double meanRatio =
        0.0;  // mean luminance of non-emitting surface pixels / the reference's: bias at a glance
    std::uint32_t emitters = 0;
};

// Renders `frames` frames of a still camera; measures the second half (temporal history first).
// The reference method restarts every frame: its point is one frame's worth of samples.
SweepPoint measureSetting(engine::gpu::Context& gpu, engine::world::Scene& scene,
                          const engine::world::CameraPreset& camera,
                          const engine::render::FrameSettings& frame,
                          engine::lighting::LightingSettings lighting, std::uint32_t frames,
                          const std::vector<glm::vec4>& reference, std::string label);

// The same on a renderer kept across measurements, so its pipelines are built once (on lavapipe
// that is most of a short measurement's time); its history is reset first. Its frame counter runs
// on, so a point depends on the measurements before it on that renderer, repeatably.
SweepPoint measureSetting(engine::render::Renderer& renderer, engine::world::Scene& scene,
                          const engine::world::CameraPreset& camera,
                          const engine::render::FrameSettings& frame,
                          engine::lighting::LightingSettings lighting, std::uint32_t frames,
                          const std::vector<glm::vec4>& reference, std::string label);

// The converged reference of a scene and view: read from `cacheDir` when an EXR with the same
// key (scene file contents, camera, size, samples, bounces, and a variant tag naming edits made
// after loading) exists, else rendered and stored.
engine::Result<std::vector<glm::vec4>> cachedReference(engine::gpu::Context& gpu,
                                                       engine::world::Scene& scene,
                                                       const engine::world::CameraPreset& camera,
                                                       const engine::render::FrameSettings& frame,
                                                       std::uint32_t spp, std::uint32_t bounces,
                                                       const std::filesystem::path& cacheDir,
                                                       const std::string& variant = {});

}  // namespace vox
