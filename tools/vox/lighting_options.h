// Command-line options for lighting, one per knob of lighting/lighting_knobs.h (so the options,
// their ranges and their help cannot drift from the scene files and the HUD), shared by the
// commands that render.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "lighting/lighting_knobs.h"
#include "world/scene.h"

namespace vox {

struct LightingOptions {
    // One slot per knob, in knobGroups() order; set when the option was given.
    std::vector<std::optional<std::string>> given;
    bool showSettings = false;  // --show-settings: print the merged settings and stop
    // The command's own defaults, under the scene's settings (scene::playerDefaults).
    std::vector<engine::lighting::KnobValue> commandDefaults;
};

void addLightingOptions(CLI::App& cmd, LightingOptions& o);
// The options given, as values that override a scene's.
std::vector<engine::lighting::KnobValue> lightingOverrides(const LightingOptions& o);
// The one merge: defaults, the scene's settings when given, then the command line's.
engine::Result<engine::lighting::LightingSettings> lightingSettings(
    const LightingOptions& o, const engine::world::Scene* scene = nullptr);
// "--method ris --sampling power" as knob values (a benchmark's variant); `where` names the source
// in messages.
engine::Result<std::vector<engine::lighting::KnobValue>> knobValuesOf(const std::string& text,
                                                                      const std::string& where);
// Every knob as `option value`, one per line: what --show-settings prints.
std::string settingsText(const engine::lighting::LightingSettings& s);

}  // namespace vox
