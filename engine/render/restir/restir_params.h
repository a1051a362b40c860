// The ReSTIR passes' parameters from the lighting settings: the one place that fills
// shared::RestirParams (shaders/shared/restir.h), for ReSTIR and for RIS (ReSTIR without reuse).
#pragma once

#include <cstdint>

#include "lighting/lighting_settings.h"
#include "shared/restir.h"

namespace engine::render {

shared::RestirParams restirParams(const lighting::LightingSettings& settings,
                                  std::uint32_t frameIndex);

}  // namespace engine::render
