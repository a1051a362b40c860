// What the GPU tests share to set up a frame, so each test file keeps only its own scenes and
// checks: the engine names they all spell, frame sizes, shipped worlds loaded by file name, scenes
// built from a palette, frames rendered with a Renderer on the test context, and the image
// statistics they compare by. A test file says `using namespace gpu_testing;`.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <initializer_list>
#include <string>
#include <vector>

#include "gpu/gpu_test_context.h"
#include "render/renderer.h"
#include "world/material.h"
#include "world/scene.h"

namespace gpu_testing {

using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::render::FrameImages;
using engine::render::FrameSettings;
using engine::render::Renderer;

// Sun and sky only, no emitter sampling: deterministic, for tests about geometry and uploads.
inline const LightingSettings kPreview{Method::Preview};

// A width x height frame (square when height is 0); every other setting at its default.
FrameSettings frame(std::uint32_t width, std::uint32_t height = 0);

// A world shipped in worlds/, by file name with or without ".toml". A failed load fails the test
// and gives an empty scene.
engine::world::Scene loadWorld(const std::string& name);

// An empty world of `size` voxels whose palette is `materials` (ids 1..n in order). With
// `darkSky`, no sun and no sky: every bit of light comes from the emitters.
engine::world::Scene paletteScene(glm::ivec3 size,
                                  std::initializer_list<engine::world::Material> materials,
                                  bool darkSky);

// One frame of `scene` from `camera` by a fresh Renderer, read back.
FrameImages renderOnce(engine::world::Scene& scene, const engine::world::CameraPreset& camera,
                       const FrameSettings& settings, const LightingSettings& lighting = kPreview);

// `frames` frames of `scene` from its first camera by `renderer` (its history carries on), the
// last one read back.
FrameImages renderFrames(Renderer& renderer, engine::world::Scene& scene,
                         const LightingSettings& lighting, const FrameSettings& settings,
                         int frames);

// Rec. 709 luminance of linear RGB.
inline double luminance(const glm::vec4& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

double meanLuminance(const std::vector<glm::vec4>& image);

// Mean absolute error over the RGB channels of every pixel (thesis eq. 3-4).
double mae(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b);

}  // namespace gpu_testing
