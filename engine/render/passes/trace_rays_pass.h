// Batch ray queries (TraceRayInput -> TraceRayOutput), for the GPU/CPU agreement tests and the
// traversal benchmark. Shaders: shaders/world/trace_rays_{hierarchical,plain,scene}.comp, one per
// mode (TRACE_MODE_*), each built the first time it is used.
#pragma once

#include <array>
#include <memory>

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
        const gpu::Buffer& params;  // read: TraceRaysParams (its mode must equal `mode`)
        const gpu::Buffer& rays;    // read: TraceRayInput[]
        gpu::Buffer& hits;          // write: TraceRayOutput[]
    };
    void record(gpu::CommandList& cmd, const Io& io, std::uint32_t rayCount, std::uint32_t mode);

private:
    gpu::Context& mCtx;
    std::array<std::unique_ptr<gpu::ComputePipeline>, 3> mPipelines;  // by TRACE_MODE_*
};

}  // namespace engine::render
