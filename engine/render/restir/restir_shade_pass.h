// Shading of the reservoir methods: emission + sun + the reservoir's light with one shadow ray.
// Shader: shaders/restir/shade.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/restir.h"

namespace engine::render {

struct RestirShadeIo {
    const gpu::Buffer& frameParams;   // read
    const gpu::Buffer& restirParams;  // read
    const gpu::Buffer& gbuffer;       // read
    gpu::Buffer& reservoirs;          // read; occluded samples lose their weight
    gpu::Buffer& radiance;            // write
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::RESTIR_BINDING_FRAME, &frameParams},
                                           {shared::RESTIR_BINDING_PARAMS, &restirParams},
                                           {shared::RESTIR_BINDING_GBUFFER, &gbuffer},
                                           {shared::RESTIR_SHADE_BINDING_FINAL, &reservoirs},
                                           {shared::RESTIR_SHADE_BINDING_RADIANCE, &radiance}});
    }
};

class RestirShadePass : public ScreenLitPass<RestirShadeIo> {
public:
    using Io = RestirShadeIo;
    explicit RestirShadePass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "restir_shade", "restir/shade") {}
};

}  // namespace engine::render
