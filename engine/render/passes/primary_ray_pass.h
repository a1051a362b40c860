// Primary rays: one camera ray per pixel through the brick grid into the G-buffer (hit voxel,
// face, material, distance, DDA steps) and the surface keys the display's passes compare.
// Shader: shaders/world/primary_rays.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "render/passes/scene_bindings.h"
#include "shared/bindings.h"

namespace engine::render {

struct PrimaryRayIo {
    const GpuWorld& world;           // read
    const gpu::Buffer& frameParams;  // read
    gpu::Buffer& gbuffer;            // write
    gpu::Buffer& surfaceKeys;        // write: uint per pixel
    auto bindings() const {
        return joinBindings(
            worldBindings(world),
            std::to_array<PassBinding>({{shared::PRIMARY_BINDING_FRAME, &frameParams},
                                        {shared::PRIMARY_BINDING_GBUFFER, &gbuffer},
                                        {shared::PRIMARY_BINDING_SURFACE_KEYS, &surfaceKeys}}));
    }
};

class PrimaryRayPass : public ScreenPass<PrimaryRayIo> {
public:
    using Io = PrimaryRayIo;
    explicit PrimaryRayPass(gpu::Context& ctx)
        : ScreenPass(ctx, "primary_rays", "world/primary_rays") {}
};

}  // namespace engine::render
