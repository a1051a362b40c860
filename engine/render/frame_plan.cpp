#include "render/frame_plan.h"

#include "render/restir/restir_params.h"
#include "shared/shader_features.h"

namespace engine::render {

SceneShape sceneShape(const world::Scene& scene) {
    return {scene.grid.sizeInVoxels(), scene.dynamic.present()};
}

bool FramePlan::runs(std::string_view technique) const {
    for (const Step& s : steps) {
        if (s.technique->name == technique) return s.plan.runs;
    }
    return false;
}

FramePlan planFrame(const lighting::LightingSettings& lighting, const SceneShape& scene,
                    glm::uvec2 size) {
    FramePlan plan;
    // Every method that samples emitters reads these (common/emitters.glsl).
    const shared::RestirParams emitters = restirParams(lighting, 0);
    plan.features[FEATURE_UNIFORM_SAMPLING] = emitters.byPower ? 0u : 1u;
    plan.features[FEATURE_POINT_LIGHTS] = emitters.area ? 0u : 1u;
    plan.features[FEATURE_DYNAMIC_GRID] = scene.dynamicGrid ? 1u : 0u;
    for (const TechniqueEntry& t : techniqueRegistry()) {
        FramePlan::Step& step =
            plan.steps.emplace_back(FramePlan::Step{&t, t.plan(lighting, scene, size)});
        if (!step.plan.runs) continue;
        for (const auto& [feature, value] : step.plan.features) plan.features[feature] = value;
        plan.addsIndirect = plan.addsIndirect || step.plan.addsIndirect;
        plan.writesDisplay = plan.writesDisplay || step.plan.writesDisplay;
    }
    return plan;
}

std::string describeLighting(const lighting::LightingSettings& lighting) {
    std::string text;
    for (const FramePlan::Step& s : planFrame(lighting, {}, {0, 0}).steps) {
        if (!s.plan.runs) continue;
        const std::string part = s.technique->describe(lighting);
        if (part.empty()) continue;
        text += text.empty() ? part : " + " + part;
    }
    return text;
}

}  // namespace engine::render
