// The reference path tracer's parameters from the lighting settings: the one place that fills
// shared::ReferenceParams (shaders/shared/reference.h).
#pragma once

#include "lighting/lighting_settings.h"
#include "shared/reference.h"

namespace engine::render {

shared::ReferenceParams referenceParams(const lighting::LightingSettings& settings);

}  // namespace engine::render
