// Preview shading: albedo x (sky ambient + sun with one shadow ray) + emission, into linear
// radiance; also per-pixel ray statistics. Shader: shaders/world/shade_sun.comp
#pragma once

#include "gpu/compute_pipeline.h"
#include "render/gpu_world.h"

namespace engine::gpu {
class CommandList;
}

namespace engine::render {

class SunShadePass {
public:
    explicit SunShadePass(gpu::Context& ctx);
    struct Io {
        const GpuWorld& world;           // read
        const gpu::Buffer& frameParams;  // read
        const gpu::Buffer& gbuffer;      // read
        gpu::Buffer& radiance;           // write: vec4 per pixel
        gpu::Buffer& rayStats;           // write: uvec4 per pixel
    };
    void record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size);

private:
    gpu::ComputePipeline mPipeline;
};

}  // namespace engine::render
