// The DVF sky term's dispatches (shaders/dvf_sky/): all share one set of buffers (DvfSkyIo).
//   dvf.invalidate  one thread per slot: directions an edit can have changed become dirty
//   dvf.take_batch  one thread: this frame's masks off the trace queue
//   dvf.build       one workgroup per queued slot, one thread per direction: trace the dirty ones
//   dvf.shade       per pixel: find (or ask for) the face's mask, add the sky it lets through
//   sky.reference   per pixel: brute-force cosine rays, the ground truth of the sky term
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/dvf_sky.h"

namespace engine::render {

struct DvfSkyIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: DvfParams
    gpu::Buffer& header;             // read and write: DvfHeader
    gpu::Buffer& slots;              // read and write: DvfSlot per slot
    gpu::Buffer& queue;              // read and write: the trace queue
    const gpu::Buffer& weights;      // read: per face and direction
    const gpu::Buffer& gbuffer;      // read
    gpu::Buffer& radiance;           // read and write: the term is added
    gpu::Buffer& sky;                // write: the term alone (and the reference's running sum)
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::DVF_BINDING_FRAME, &frameParams},
                                           {shared::DVF_BINDING_PARAMS, &params},
                                           {shared::DVF_BINDING_HEADER, &header},
                                           {shared::DVF_BINDING_SLOTS, &slots},
                                           {shared::DVF_BINDING_QUEUE, &queue},
                                           {shared::DVF_BINDING_WEIGHTS, &weights},
                                           {shared::DVF_BINDING_GBUFFER, &gbuffer},
                                           {shared::DVF_BINDING_RADIANCE, &radiance},
                                           {shared::DVF_BINDING_SKY, &sky}});
    }
};

// A dispatch of one dvf_sky shader over DvfSkyIo's buffers with a given number of workgroups.
class DvfSkyPass {
public:
    DvfSkyPass(gpu::Context& ctx, std::string name, const std::string& shader)
        : mPass(ctx, std::move(name), shader, bindingCount<DvfSkyIo>()) {}
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const DvfSkyIo& io,
                glm::uvec2 groups) {
        mPass.record(cmd, scene, io.bindings(), groups);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
