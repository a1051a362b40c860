#include "render/shader_features.h"

#include "render/frame_plan.h"

namespace engine::render {

ShaderFeatures shaderFeatures(const lighting::LightingSettings& l, bool dynamicGrid) {
    SceneShape scene;
    scene.dynamicGrid = dynamicGrid;
    return planFrame(l, scene, {0, 0}).features;
}

}  // namespace engine::render
