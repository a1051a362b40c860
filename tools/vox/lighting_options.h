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
};

void addLightingOptions(CLI::App& cmd, LightingOptions& o);
engine::Result<engine::lighting::LightingSettings> lightingSettings(const LightingOptions& o);

}  // namespace vox
