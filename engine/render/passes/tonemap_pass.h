// Tonemapping: linear radiance -> exposure -> ACES fit -> sRGB RGBA8. Shader: shaders/post/tonemap.comp
#pragma once

#include <glm/glm.hpp>

#include "gpu/compute_pipeline.h"

namespace engine::gpu {
class CommandList;
}

namespace engine::render {

class TonemapPass {
public:
    explicit TonemapPass(gpu::Context& ctx);
    struct Io {
        const gpu::Buffer& frameParams;  // read
        const gpu::Buffer& radiance;     // read
        gpu::Buffer& ldr;                // write: packed RGBA8 per pixel
    };
    void record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size);

private:
    gpu::ComputePipeline mPipeline;
};

}  // namespace engine::render
