// The path-traced indirect term's one dispatch: bounce paths from the G-buffer's surfaces into a
// running sum per pixel; writes the mean as the frame's indirect term and adds it to the radiance.
// Shader: shaders/path_indirect/trace_paths.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/path_indirect.h"

namespace engine::render {

struct PathIndirectIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: PathIndirectParams
    const gpu::Buffer& gbuffer;      // read
    gpu::Buffer& accumulation;       // read and write
    gpu::Buffer& indirect;           // write
    gpu::Buffer& radiance;           // read and write: the term is added
    auto bindings() const {
        return std::to_array<PassBinding>(
            {{shared::PATH_INDIRECT_BINDING_FRAME, &frameParams},
             {shared::PATH_INDIRECT_BINDING_PARAMS, &params},
             {shared::PATH_INDIRECT_BINDING_GBUFFER, &gbuffer},
             {shared::PATH_INDIRECT_BINDING_ACCUMULATION, &accumulation},
             {shared::PATH_INDIRECT_BINDING_INDIRECT, &indirect},
             {shared::PATH_INDIRECT_BINDING_RADIANCE, &radiance}});
    }
};

class PathIndirectPass : public ScreenLitPass<PathIndirectIo> {
public:
    using Io = PathIndirectIo;
    explicit PathIndirectPass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "path.trace", "path_indirect/trace_paths") {}
};

}  // namespace engine::render
