#include "render/passes/preview_shading.h"

#include "render/frame_commands.h"

namespace engine::render {

TechniquePlan PreviewShading::plan(const lighting::LightingSettings& l, const SceneShape&,
                                   glm::uvec2) {
    TechniquePlan p;
    p.runs = l.method == lighting::Method::Preview;
    return p;
}

std::string PreviewShading::describe(const lighting::LightingSettings&) { return "preview"; }

void PreviewShading::record(FrameCommands& commands, const FrameBuffers& frame) {
    mPass.record(
        commands.current(),
        {frame.scene.world, frame.frameParams, frame.gbuffer, frame.radiance, frame.rayStats},
        frame.size);
}

}  // namespace engine::render
