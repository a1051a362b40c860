// Command-line options for lighting settings, shared by the commands that render.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "world/scene.h"

namespace vox {

struct LightingOptions {
    std::string method = "restir";
    std::string mode = "area";
    std::string sampling = "power";
    std::uint32_t candidates = 32;
    std::string brickLights = "on";
    std::string spatial = "5,30";
    std::string temporal = "on";
    std::uint32_t shadowRays = 1;
    std::uint32_t bounces = 0;
    std::string pixelFilter = "box";
    std::uint32_t seed = 1;
    // Unset: the scene file's [indirect] table decides, else the defaults of IrradianceCacheSettings.
    std::optional<std::string> indirect;
    std::optional<std::uint32_t> cacheDirections, cacheRays, cacheBounces, cacheNeighbourhood;
    std::optional<float> cacheAlpha, cacheMaxRay;
    std::optional<std::string> cacheFilter;
    std::optional<double> cacheBudgetMb;
};

void addLightingOptions(CLI::App& cmd, LightingOptions& o);
// `scene`, when given, supplies the indirect-light settings the command line leaves unset.
engine::Result<engine::lighting::LightingSettings> lightingSettings(const LightingOptions& o,
                                                                   const engine::world::Scene* scene = nullptr);

}  // namespace vox
