#include "render/baselines/light_sampling_params.h"

namespace engine::render {

shared::LightSamplingParams lightSamplingParams(const lighting::LightingSettings& l,
                                                std::uint32_t frameIndex) {
    shared::LightSamplingParams p{};
    p.samples = l.shadowRays;
    p.everyLight = l.method == lighting::Method::BruteForce ? 1u : 0u;
    p.area = l.area ? 1u : 0u;
    p.byPower = l.byPower ? 1u : 0u;
    p.frameIndex = frameIndex;
    p.seed = l.seed;
    return p;
}

}  // namespace engine::render
