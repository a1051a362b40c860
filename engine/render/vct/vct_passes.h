// Voxel cone tracing's two dispatches: the injection of the radiance clipmap (one invocation per
// texel, every level; shaders/vct/inject_radiance.comp) and the per-pixel cone gather
// (shaders/vct/trace_cones.comp), which writes the indirect term and adds it to the radiance.
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/vct.h"

namespace engine::render {

struct VctInjectIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: VctParams
    const gpu::Buffer& previous;     // read: the last frame's volume (the extra bounce)
    gpu::Buffer& volume;             // write
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::VCT_INJECT_BINDING_FRAME, &frameParams},
                                           {shared::VCT_INJECT_BINDING_PARAMS, &params},
                                           {shared::VCT_INJECT_BINDING_PREVIOUS, &previous},
                                           {shared::VCT_INJECT_BINDING_VOLUME, &volume}});
    }
};

class VctInjectPass {
public:
    explicit VctInjectPass(gpu::Context& ctx)
        : mPass(ctx, "vct.inject", "vct/inject_radiance", bindingCount<VctInjectIo>()) {}
    // Texels as a 2D grid: x, then y + RES * (z + RES * level).
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const VctInjectIo& io,
                std::uint32_t levels) {
        mPass.record(cmd, scene, io.bindings(),
                     screenGroups({shared::VCT_RES, shared::VCT_RES * shared::VCT_RES * levels}));
    }

private:
    LitPass mPass;
};

struct VctConesIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: VctParams
    const gpu::Buffer& gbuffer;      // read
    const gpu::Buffer& volume;       // read
    gpu::Buffer& indirect;           // write
    gpu::Buffer& radiance;           // read and write: the term is added
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::VCT_CONES_BINDING_FRAME, &frameParams},
                                           {shared::VCT_CONES_BINDING_PARAMS, &params},
                                           {shared::VCT_CONES_BINDING_GBUFFER, &gbuffer},
                                           {shared::VCT_CONES_BINDING_VOLUME, &volume},
                                           {shared::VCT_CONES_BINDING_INDIRECT, &indirect},
                                           {shared::VCT_CONES_BINDING_RADIANCE, &radiance}});
    }
};

class VctConesPass : public ScreenLitPass<VctConesIo> {
public:
    using Io = VctConesIo;
    explicit VctConesPass(gpu::Context& ctx) : ScreenLitPass(ctx, "vct.cones", "vct/trace_cones") {}
};

}  // namespace engine::render
