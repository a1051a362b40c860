#include "render/restir/restir_params.h"

namespace engine::render {

shared::RestirParams restirParams(const lighting::LightingSettings& l, std::uint32_t frameIndex) {
    const bool restir = l.method == lighting::Method::Restir;  // else RIS: no reuse
    shared::RestirParams p{};
    p.candidates = l.candidates;
    p.spatialTaps = l.spatialTaps;
    p.frameIndex = frameIndex;
    p.seed = l.seed;
    p.spatialRadius = l.spatialRadius;
    p.temporalCap = l.temporalCap;
    p.depthTolerance = l.depthTolerance;
    p.area = l.area ? 1u : 0u;
    p.byPower = l.byPower ? 1u : 0u;
    p.unbiased = restir && l.unbiased ? 1u : 0u;
    p.temporal = restir && l.temporal ? 1u : 0u;
    p.spatial = restir && l.spatial ? 1u : 0u;
    // The unbiased normalisation counts neighbours by visibility, which is only right when every
    // stored reservoir's weight already accounts for its own sample's visibility.
    p.candidateVisibility = restir && (l.candidateVisibility || l.unbiased) ? 1u : 0u;
    return p;
}

}  // namespace engine::render
