// Voxel cone tracing's dispatches: the injection of the radiance clipmap — vct.classify (one
// invocation per texel of the blocks the host listed, vct_block_list.h: copies kept texels, zeroes
// empty ones, lists the rest; shaders/vct/classify_texels.comp), vct.list_dispatch (the list's
// workgroup count) and vct.inject (indirect, one invocation per listed texel; inject_radiance.comp)
// — and the per-pixel cone gather (shaders/vct/trace_cones.comp), which writes the indirect term
// and adds it to the radiance.
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/vct.h"

namespace engine::render {

struct VctInjectIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: VctParams
    const gpu::Buffer& previous;     // read: the last frame's volume (kept texels, extra bounce)
    gpu::Buffer& volume;             // write
    gpu::Buffer& list;               // read and write: the texels to inject (shared/vct.h)
    const gpu::Buffer& blocks;       // read: the blocks of texels vct.classify visits
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::VCT_INJECT_BINDING_FRAME, &frameParams},
                                           {shared::VCT_INJECT_BINDING_PARAMS, &params},
                                           {shared::VCT_INJECT_BINDING_PREVIOUS, &previous},
                                           {shared::VCT_INJECT_BINDING_VOLUME, &volume},
                                           {shared::VCT_INJECT_BINDING_LIST, &list},
                                           {shared::VCT_INJECT_BINDING_BLOCKS, &blocks}});
    }
};

class VctInjectPass {
public:
    explicit VctInjectPass(gpu::Context& ctx)
        : mClassify(ctx, "vct.classify", "vct/classify_texels", bindingCount<VctInjectIo>()),
          mListDispatch(ctx, "vct.list_dispatch", "vct/list_dispatch", bindingCount<VctInjectIo>()),
          mInject(ctx, "vct.inject", "vct/inject_radiance", bindingCount<VctInjectIo>()) {}
    // The list's bytes: its header and one index per texel of every level.
    static std::uint64_t listBytes() {
        return (shared::VCT_LIST_HEADER +
                std::uint64_t(shared::VCT_MAX_LEVELS) * shared::VCT_TEXELS_PER_LEVEL) *
               4u;
    }
    // The blocks' bytes: every block of every level.
    static std::uint64_t blocksBytes() {
        return std::uint64_t(shared::VCT_MAX_LEVELS) * shared::VCT_BLOCKS_PER_LEVEL * 4u;
    }
    // Over the first `blocks` entries of io.blocks; the list's count must be 0 (the caller clears
    // the list first).
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const VctInjectIo& io,
                std::uint32_t blocks) {
        const auto bindings = io.bindings();
        mClassify.record(cmd, scene, bindings, {blocks, 1u});
        mListDispatch.record(cmd, scene, bindings, {1u, 1u});
        mInject.recordIndirect(cmd, scene, bindings, io.list, shared::VCT_LIST_ARGS * 4u);
    }

private:
    LitPass mClassify, mListDispatch, mInject;
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
