// The light-sampling baselines' parameters from the lighting settings: the one place that fills
// shared::LightSamplingParams (shaders/shared/light_sampling.h).
#pragma once

#include <cstdint>

#include "lighting/lighting_settings.h"
#include "shared/light_sampling.h"

namespace engine::render {

shared::LightSamplingParams lightSamplingParams(const lighting::LightingSettings& settings,
                                                std::uint32_t frameIndex);

}  // namespace engine::render
