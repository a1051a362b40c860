// The knob tables of LightingSettings, one group per technique, and the one path every entry
// point (command line, scene files, HUD, benches) takes: overrides applied in order onto the
// defaults, then normalised and validated the same way.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "lighting/knob.h"
#include "lighting/lighting_settings.h"

namespace engine::lighting {

struct KnobGroup {
    std::string_view
        name;  // the technique: lighting, emitters, restir, baselines, reference, cache, path
    std::string_view cliPrefix;  // "cache-" makes --cache-rays; scene files use the bare name
    std::span<const Knob> knobs;
};

std::span<const KnobGroup> knobGroups();
const KnobGroup& knobGroup(std::string_view name);
// The knob a command-line option (without "--") names, or null.
const Knob* knobForOption(std::string_view option);
// "--cache-max-ray" for the cache's max_ray.
std::string knobOption(const KnobGroup& group, const Knob& knob);

// One value from an entry point; `where` names it in messages ("--candidates", "a.toml:12").
struct KnobValue {
    const Knob* knob = nullptr;
    std::string text;
    std::string where;
};

// Every knob in range, plus the rules between knobs. Messages name the knob.
Status validate(const LightingSettings& s);

// The defaults, then each layer of values in order (a scene's, then the command line's), then
// the implications between methods (RIS has no reuse; indirect = reference makes the method the
// path tracer with at least one bounce), then validate.
Result<LightingSettings> mergeLighting(std::span<const std::vector<KnobValue>> layers);
// The same onto settings already merged (the HUD's edits).
Result<LightingSettings> mergeLighting(LightingSettings base, std::span<const KnobValue> values);

}  // namespace engine::lighting
