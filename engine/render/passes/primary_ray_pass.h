// Primary rays: one camera ray per pixel through the brick grid into the G-buffer (hit voxel,
// face, material, distance, DDA steps). Shader: shaders/world/primary_rays.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "render/passes/scene_bindings.h"
#include "shared/bindings.h"

namespace engine::render {

class PrimaryRayPass {
public:
    struct Io {
        const GpuWorld& world;          // read
        const gpu::Buffer& frameParams; // read
        gpu::Buffer& gbuffer;           // write
        auto bindings() const {
            return joinBindings(worldBindings(world),
                                std::to_array<PassBinding>({{shared::PRIMARY_BINDING_FRAME, &frameParams},
                                                            {shared::PRIMARY_BINDING_GBUFFER, &gbuffer}}));
        }
    };
    explicit PrimaryRayPass(gpu::Context& ctx) : mPass(ctx, "primary_rays", "world/primary_rays", bindingCount<Io>()) {}
    void record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size) { mPass.record(cmd, io.bindings(), screenGroups(size)); }

private:
    ComputePass mPass;
};

}  // namespace engine::render
