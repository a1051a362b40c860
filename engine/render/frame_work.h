// The work a frame lit with given settings issues, counted per kind from the settings and the
// dispatch size alone: no clock, so a cost built on it does not move with the machine's load.
// The counts are the work issued per dispatched pixel, as the passes are written
// (shaders/restir/, shaders/baselines/): what a shader skips at run time (sky pixels, neighbours
// rejected by the depth and normal test, the shadow ray of a zero contribution) is not subtracted,
// so a kind's fitted cost is per issued unit, its early-outs averaged in.
// What a kind costs is measured separately (metrics/cost_model.h); tools/vox's benches scale rows
// to equal cost with it.
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <string_view>

#include "lighting/lighting_settings.h"

namespace engine::render {

enum class WorkKind : std::size_t {
    Pixels,        // a pixel's frame: G-buffer ray, the shading pass, the passes' fixed part
    LightSamples,  // the baselines' light samples: an emitter drawn, evaluated, its shadow ray
    Candidates,    // ReSTIR's and RIS's candidates: an emitter drawn and its target evaluated
    ShadowRays,    // the resampling methods' shadow rays: candidate visibility, shading, reuse
    ReuseTaps,     // target evaluations of reused reservoirs (temporal and spatial neighbours)
};
constexpr std::size_t kWorkKinds = 5;

struct FrameWork {
    std::array<double, kWorkKinds> count{};  // per frame, indexed by WorkKind
    double& operator[](WorkKind k) { return count[std::size_t(k)]; }
    double operator[](WorkKind k) const { return count[std::size_t(k)]; }
};

// One frame's work at image `size` on a scene with `emitters` lights (brute force samples each);
// Preview and Reference count their pixels only.
FrameWork frameWork(const lighting::LightingSettings& l, glm::uvec2 size, std::uint32_t emitters);

std::string_view workKindName(WorkKind k);  // "pixels", "light samples", ...

}  // namespace engine::render
