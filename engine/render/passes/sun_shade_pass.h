// Preview shading: albedo x (sky ambient + sun with one shadow ray) + emission, into linear
// radiance; also per-pixel ray statistics. Shader: shaders/world/shade_sun.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "render/passes/scene_bindings.h"
#include "shared/bindings.h"

namespace engine::render {

struct SunShadeIo {
    const GpuWorld& world;           // read
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& gbuffer;      // read
    gpu::Buffer& radiance;           // write: vec4 per pixel
    gpu::Buffer& rayStats;           // write: uvec4 per pixel
    auto bindings() const {
        return joinBindings(
            worldBindings(world),
            std::to_array<PassBinding>({{shared::SUN_BINDING_FRAME, &frameParams},
                                        {shared::SUN_BINDING_GBUFFER, &gbuffer},
                                        {shared::SUN_BINDING_RADIANCE, &radiance},
                                        {shared::SUN_BINDING_RAY_STATS, &rayStats}}));
    }
};

class SunShadePass : public ScreenPass<SunShadeIo> {
public:
    using Io = SunShadeIo;
    explicit SunShadePass(gpu::Context& ctx) : ScreenPass(ctx, "shade_sun", "world/shade_sun") {}
};

}  // namespace engine::render
