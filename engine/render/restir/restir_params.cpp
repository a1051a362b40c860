#include "render/restir/restir_params.h"

namespace engine::render {

shared::RestirParams restirParams(const lighting::LightingSettings& l, std::uint32_t frameIndex) {
    const bool restir = l.method == lighting::Method::Restir;  // else RIS: no reuse
    shared::RestirParams p{};
    p.knobs = l.restir;
    p.knobs.unbiased = restir && l.restir.unbiased ? 1u : 0u;
    p.knobs.temporal = restir && l.restir.temporal ? 1u : 0u;
    p.knobs.spatial = restir && l.restir.spatial ? 1u : 0u;
    // The unbiased normalisation counts neighbours by visibility, which is only right when every
    // stored reservoir's weight already accounts for its own sample's visibility.
    p.knobs.candidateVisibility =
        restir && (l.restir.candidateVisibility || l.restir.unbiased) ? 1u : 0u;
    p.area = l.area ? 1u : 0u;
    p.byPower = l.byPower ? 1u : 0u;
    p.frameIndex = frameIndex;
    p.seed = l.seed;
    return p;
}

}  // namespace engine::render
