// Primary rays: one camera ray per pixel through the brick grid into the G-buffer (hit voxel,
// face, material, distance, DDA steps). Shader: shaders/world/primary_rays.comp
#pragma once

#include "gpu/compute_pipeline.h"
#include "render/gpu_world.h"

namespace engine::gpu {
class CommandList;
}

namespace engine::render {

class PrimaryRayPass {
public:
    explicit PrimaryRayPass(gpu::Context& ctx);
    struct Io {
        const GpuWorld& world;          // read
        const gpu::Buffer& frameParams; // read
        gpu::Buffer& gbuffer;           // write
    };
    void record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size);

private:
    gpu::ComputePipeline mPipeline;
};

}  // namespace engine::render
