// PreviewShading: `--method preview`, for looking at worlds — sun with one shadow ray, sky
// ambient and emission, no emitter lighting (SunShadePass), with ray statistics per pixel.
#pragma once

#include <string>

#include "render/passes/sun_shade_pass.h"
#include "render/technique.h"

namespace engine::render {

class PreviewShading : public Technique {
public:
    explicit PreviewShading(gpu::Context& ctx) : mPass(ctx) {}
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges&, const FrameInput&, gpu::Uploader&,
                 shared::FrameParams&) override {}
    void record(FrameCommands& commands, const FrameBuffers& frame) override;

private:
    SunShadePass mPass;
};

}  // namespace engine::render
