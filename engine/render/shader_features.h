// Which optional shader code a frame needs (shaders/shared/shader_features.h): the values of the
// specialization constants every pass of the frame is compiled with. The frame plan's
// (frame_plan.h): each running technique's features, the emitters' sampling, and whether the
// scene has a dynamic grid this frame (world::DynamicGrid::present, which also sets the GPU
// world's flag), so a feature the frame uses is never compiled out; the features it does not use
// cost nothing on lavapipe.
#pragma once

#include <array>
#include <cstdint>

#include "lighting/lighting_settings.h"
#include "shared/shader_features.h"

namespace engine::render {

using ShaderFeatures = std::array<std::uint32_t, FEATURE_COUNT>;

// The features of a frame lit with `l` (planFrame(...).features).
ShaderFeatures shaderFeatures(const lighting::LightingSettings& l, bool dynamicGrid);

}  // namespace engine::render
