// Rays a frame traces, for the commands that report them (`vox capture`, `vox bench frame`).
// The preview shading counts its rays on the GPU; the other methods do not, so their count is
// bounded from per-pixel counts (docs/CAPTURE.md), plus the irradiance cache's own rays, which
// the cache counts exactly.
#pragma once

#include <cstdint>

#include "lighting/lighting_settings.h"
#include "render/renderer.h"
#include "world/scene.h"

namespace vox {

// Primary rays (`pixels`) plus, per pixel whose primary ray hit a surface (`surface`), the rays
// the method's shaders trace at most — a shadow ray is skipped where its light cannot
// contribute (behind the surface, zero target), so this is an upper bound — plus the cache's rays.
std::uint64_t rayBound(const engine::lighting::LightingSettings& l,
                       const engine::world::Scene& scene, const engine::render::FrameResult& r,
                       std::uint64_t pixels, std::uint64_t surface);

// Pixels of a read-back frame whose primary ray hit a surface.
std::uint64_t surfacePixels(const engine::render::FrameImages& images);

}  // namespace vox
