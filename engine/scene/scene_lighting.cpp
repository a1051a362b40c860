#include "scene/scene_lighting.h"

#include <fmt/format.h>
#include <string>

#include "scene/indirect_keys.h"

namespace engine::scene {

std::vector<lighting::KnobValue> sceneLightingValues(const world::Scene& scene) {
    const std::string where =
        fmt::format("{} [indirect]", scene.sourcePath.empty() ? scene.name : scene.sourcePath);
    std::vector<lighting::KnobValue> values;
    for (const auto& [key, text] : scene.indirect) {
        if (const lighting::Knob* k = indirectKnob(key)) values.push_back({k, text, where});
    }
    if (!scene.sky.lightMode.empty()) {
        const std::string skyWhere =
            fmt::format("{} [sky]", scene.sourcePath.empty() ? scene.name : scene.sourcePath);
        values.push_back({lighting::knobForOption("sky"), scene.sky.lightMode, skyWhere});
    }
    return values;
}

Result<lighting::LightingSettings> lightingFor(
    const world::Scene* scene, std::span<const lighting::KnobValue> overrides,
    std::span<const lighting::KnobValue> commandDefaults) {
    std::vector<std::vector<lighting::KnobValue>> layers;
    layers.emplace_back(commandDefaults.begin(), commandDefaults.end());
    if (scene) layers.push_back(sceneLightingValues(*scene));
    layers.emplace_back(overrides.begin(), overrides.end());
    return lighting::mergeLighting(layers);
}

std::vector<lighting::KnobValue> playerDefaults(bool autoExposure) {
    const char* where = "the player's defaults";
    std::vector<lighting::KnobValue> values{
        {lighting::knobForOption("display"), "denoised", where}};
    if (autoExposure) values.push_back({lighting::knobForOption("auto-exposure"), "on", where});
    return values;
}

std::vector<lighting::KnobValue> playDefaults() {
    std::vector<lighting::KnobValue> values = playerDefaults();
    values.push_back({lighting::knobForOption("indirect"), "cache", "vox play's defaults"});
    return values;
}

}  // namespace engine::scene
