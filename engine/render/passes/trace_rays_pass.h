// Batch ray queries (TraceRayInput -> TraceRayOutput), for the GPU/CPU agreement tests and the
// traversal benchmark. Shader: shaders/world/trace_rays.comp
#pragma once

#include "gpu/compute_pipeline.h"
#include "render/gpu_world.h"

namespace engine::gpu {
class CommandList;
}

namespace engine::render {

class TraceRaysPass {
public:
    explicit TraceRaysPass(gpu::Context& ctx);
    struct Io {
        const GpuWorld& world;      // read
        const gpu::Buffer& params;  // read: TraceRaysParams
        const gpu::Buffer& rays;    // read: TraceRayInput[]
        gpu::Buffer& hits;          // write: TraceRayOutput[]
    };
    void record(gpu::CommandList& cmd, const Io& io, std::uint32_t rayCount);

private:
    gpu::ComputePipeline mPipeline;
};

}  // namespace engine::render
