// Batch ray queries (TraceRayInput -> TraceRayOutput), for the GPU/CPU agreement tests and the
// traversal benchmark. Shaders: shaders/world/trace_rays_{hierarchical,plain,scene}.comp, one per
// mode (TRACE_MODE_*), each built the first time it is used.
#pragma once

#include <array>
#include <memory>

#include "render/passes/compute_pass.h"
#include "render/passes/scene_bindings.h"
#include "shared/bindings.h"

namespace engine::render {

class TraceRaysPass {
public:
    explicit TraceRaysPass(gpu::Context& ctx);
    struct Io {
        const GpuWorld& world;      // read
        const gpu::Buffer& params;  // read: TraceRaysParams (its mode must equal `mode`)
        const gpu::Buffer& rays;    // read: TraceRayInput[]
        gpu::Buffer& hits;          // write: TraceRayOutput[]
        auto bindings() const {
            return joinBindings(worldBindings(world),
                                std::to_array<PassBinding>({{shared::TRACE_BINDING_PARAMS, &params},
                                                            {shared::TRACE_BINDING_RAYS, &rays},
                                                            {shared::TRACE_BINDING_HITS, &hits}}));
        }
    };
    void record(gpu::CommandList& cmd, const Io& io, std::uint32_t rayCount, std::uint32_t mode);

private:
    gpu::Context& mCtx;
    std::array<std::unique_ptr<ComputePass>, 3> mPasses;  // by TRACE_MODE_*
};

}  // namespace engine::render
