// LitPass: the shape every light-sampling pass shares — one compute shader over a screen-sized
// grid that reads the world (bindings 0-3) and the emitter list (4-7), then its own buffers
// from binding 8 on. The concrete passes (restir_*_pass.h, light_sampling_pass.h,
// reference_pass.h) name their buffers; this class only does the binding and dispatch.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/compute_pipeline.h"
#include "lighting/gpu_emitter_list.h"
#include "render/gpu_world.h"

namespace engine::gpu {
class CommandList;
}

namespace engine::render {

struct SceneBindings {
    const GpuWorld& world;
    const lighting::GpuEmitterList& lights;
};

class LitPass {
public:
    LitPass(gpu::Context& ctx, std::string name, const std::string& shader, std::uint32_t ownBindings);
    void record(gpu::CommandList& cmd, const SceneBindings& scene, std::initializer_list<const gpu::Buffer*> own,
                glm::uvec2 size);

private:
    std::string mName;
    std::uint32_t mOwnBindings;
    gpu::ComputePipeline mPipeline;
};

}  // namespace engine::render
