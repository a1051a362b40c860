// Command-line options for lighting settings, shared by the commands that render.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "core/error.h"
#include "lighting/lighting_settings.h"

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
    std::uint32_t seed = 1;
    std::string indirect = "none";
    std::uint32_t cacheDirections = 128;
    std::uint32_t cacheRays = 16;
    std::uint32_t cacheBounces = 1;
    float cacheAlpha = 0.03f;
    std::uint32_t cacheNeighbourhood = 5;
    float cacheMaxRay = 250.0f;
    std::string cacheFilter = "on";
    double cacheBudgetMb = 64.0;
};

void addLightingOptions(CLI::App& cmd, LightingOptions& o);
engine::Result<engine::lighting::LightingSettings> lightingSettings(const LightingOptions& o);

}  // namespace vox
