// ReSTIR initial candidates (thesis §4.4-4.5): M light samples per pixel resampled into one
// reservoir, optionally shadow-tested. Shader: shaders/restir/initial_candidates.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/restir.h"

namespace engine::render {

class RestirInitialPass {
public:
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        const gpu::Buffer& gbuffer;       // read
        gpu::Buffer& reservoirs;          // write
        auto bindings() const {
            return std::to_array<PassBinding>({{shared::RESTIR_BINDING_FRAME, &frameParams},
                                               {shared::RESTIR_BINDING_PARAMS, &restirParams},
                                               {shared::RESTIR_BINDING_GBUFFER, &gbuffer},
                                               {shared::RESTIR_INITIAL_BINDING_OUT, &reservoirs}});
        }
    };
    explicit RestirInitialPass(gpu::Context& ctx)
        : mPass(ctx, "restir_initial", "restir/initial_candidates", bindingCount<Io>()) {}
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, io.bindings(), screenGroups(size));
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
