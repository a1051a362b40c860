#include "render/frame_work.h"

#include <algorithm>

#include "render/restir/restir_params.h"

namespace engine::render {

namespace {

// Per pixel: the resampling passes (shaders/restir/) as restirParams() switches them for the
// method (RIS: candidates and shading only).
void countResampling(const lighting::LightingSettings& l, FrameWork& w) {
    const shared::RestirKnobs k = restirParams(l, 0).knobs;
    w[WorkKind::Candidates] = k.candidates;
    w[WorkKind::ShadowRays] = 1.0;  // shade.comp's shadow ray
    if (k.candidateVisibility) w[WorkKind::ShadowRays] += 1.0;
    double taps = 0.0;
    if (k.temporal) {
        taps += 1.0;  // last frame's reservoir evaluated here
        // Unbiased: the candidate's sample also at last frame's surface, with its shadow ray.
        if (k.unbiased) {
            taps += 1.0;
            w[WorkKind::ShadowRays] += 1.0;
        }
    }
    if (k.spatial) {
        // Biased: each neighbour's sample here, then the chosen one at each neighbour (the
        // normaliser); unbiased (pairwise MIS): the same two evaluations per neighbour.
        taps += 2.0 * double(k.spatialTaps);
    }
    w[WorkKind::ReuseTaps] = taps;
}

}  // namespace

FrameWork frameWork(const lighting::LightingSettings& l, glm::uvec2 size, std::uint32_t emitters) {
    FrameWork perPixel;
    perPixel[WorkKind::Pixels] = 1.0;
    switch (l.method) {
        case lighting::Method::Uniform:
            perPixel[WorkKind::LightSamples] = double(std::max(l.shadowRays, 1u));
            break;
        case lighting::Method::BruteForce:
            perPixel[WorkKind::LightSamples] = double(emitters);
            break;
        case lighting::Method::Ris:
        case lighting::Method::Restir:
            countResampling(l, perPixel);
            break;
        case lighting::Method::Preview:
        case lighting::Method::Reference:
            break;
    }
    const double pixels = double(size.x) * double(size.y);
    FrameWork w;
    for (std::size_t i = 0; i < kWorkKinds; ++i) w.count[i] = perPixel.count[i] * pixels;
    return w;
}

std::string_view workKindName(WorkKind k) {
    switch (k) {
        case WorkKind::Pixels:
            return "pixels";
        case WorkKind::LightSamples:
            return "light samples";
        case WorkKind::Candidates:
            return "candidates";
        case WorkKind::ShadowRays:
            return "shadow rays";
        case WorkKind::ReuseTaps:
            return "reuse taps";
    }
    return "?";
}

}  // namespace engine::render
