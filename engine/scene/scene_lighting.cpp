#include "scene/scene_lighting.h"

#include <string>

namespace engine::scene {

std::vector<lighting::KnobValue> sceneLightingValues(const world::Scene& scene) {
    lighting::LightingSettings s;
    s.indirect = scene.indirect;
    s.cache = scene.cache;
    const std::string where = scene.sourcePath.empty() ? scene.name : scene.sourcePath;
    std::vector<lighting::KnobValue> values = lighting::knobValues(lighting::knobGroup("cache"), s, where);
    for (const lighting::Knob& k : lighting::knobGroup("lighting").knobs) {
        if (k.name == "indirect") values.push_back({&k, knobText(k, s), where});
    }
    return values;
}

Result<lighting::LightingSettings> lightingFor(const world::Scene* scene, std::span<const lighting::KnobValue> overrides) {
    std::vector<std::vector<lighting::KnobValue>> layers;
    if (scene) layers.push_back(sceneLightingValues(*scene));
    layers.emplace_back(overrides.begin(), overrides.end());
    return lighting::mergeLighting(layers);
}

}  // namespace engine::scene
