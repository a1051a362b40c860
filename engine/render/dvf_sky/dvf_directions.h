// The discrete visibility field's directions on the host: the same hemi-octahedral map as
// shaders/dvf_sky/dvf_sky.glsl (8x8 texels about a face normal) and the per-face weights the
// shading pass sums over a mask's visible texels.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "shared/dvf_sky.h"

namespace engine::render {

// Direction through `uv` (in [0,1]² of the grid) of face `face`'s hemisphere.
glm::vec3 dvfDirection(std::uint32_t face, glm::vec2 uv);
// The texel a direction of the face's hemisphere falls in.
std::uint32_t dvfTexel(std::uint32_t face, glm::vec3 dir);

// weights[face * 64 + d] = (1/pi) ∫ over texel d of g(ω) cos θ dω, where g is the sky's gradient
// (common/surface.glsl: skyBackground = skyRadiance * mix(0.6, 1.4, up)): so a face that sees the
// whole sky gets albedo * skyRadiance * Σ weights, the sky's direct light on it.
std::array<float, 6 * shared::DVF_DIRECTIONS> dvfSkyWeights();

}  // namespace engine::render
