// ReSTIR spatial reuse (thesis §4.6): merges each pixel's own reservoir with the candidate
// reservoirs of k neighbours in an r-pixel disc. Shader: shaders/restir/spatial_reuse.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/restir.h"

namespace engine::render {

class RestirSpatialPass {
public:
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        const gpu::Buffer& gbuffer;       // read
        const gpu::Buffer& own;           // read: after temporal reuse, or the candidates
        const gpu::Buffer& candidates;    // read: what neighbours contribute
        gpu::Buffer& output;              // write
        auto bindings() const {
            return std::to_array<PassBinding>({{shared::RESTIR_BINDING_FRAME, &frameParams},
                                               {shared::RESTIR_BINDING_PARAMS, &restirParams},
                                               {shared::RESTIR_BINDING_GBUFFER, &gbuffer},
                                               {shared::RESTIR_SPATIAL_BINDING_OWN, &own},
                                               {shared::RESTIR_SPATIAL_BINDING_CANDIDATES, &candidates},
                                               {shared::RESTIR_SPATIAL_BINDING_OUT, &output}});
        }
    };
    explicit RestirSpatialPass(gpu::Context& ctx)
        : mPass(ctx, "restir_spatial", "restir/spatial_reuse", bindingCount<Io>()) {}
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, io.bindings(), screenGroups(size));
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
