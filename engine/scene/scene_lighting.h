// The lighting a scene asks for (its [indirect] table) merged with the overrides of an entry
// point: the one path from a scene file and a command line to LightingSettings, taken by
// `vox render`, `vox capture` and `vox play` alike.
#pragma once

#include <span>
#include <vector>

#include "core/error.h"
#include "lighting/lighting_knobs.h"
#include "world/scene.h"

namespace engine::scene {

// The scene's settings as knob values (its [indirect] mode and cache knobs).
std::vector<lighting::KnobValue> sceneLightingValues(const world::Scene& scene);
// Defaults, then the entry point's own defaults (`commandDefaults`), then the scene's values
// (when given), then `overrides`; normalised and validated.
Result<lighting::LightingSettings> lightingFor(
    const world::Scene* scene, std::span<const lighting::KnobValue> overrides,
    std::span<const lighting::KnobValue> commandDefaults = {});

// What a player is shown unless the scene or the command line say otherwise (`vox play`,
// `vox render`): the image reconstructed at the display's size and denoised, the exposure
// metered. Without `autoExposure` (a fixed --exposure was given) the exposure stays fixed.
std::vector<lighting::KnobValue> playerDefaults(bool autoExposure = true);
// `vox play`'s: the player's, with full lighting — ReSTIR's direct light and the irradiance
// cache's indirect, whose rays see the sky too (so no separate sky term). A scene's [indirect]
// mode or `--indirect none` still wins.
std::vector<lighting::KnobValue> playDefaults();

}  // namespace engine::scene
