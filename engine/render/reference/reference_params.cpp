#include "render/reference/reference_params.h"

namespace engine::render {

shared::ReferenceParams referenceParams(const lighting::LightingSettings& l) {
    std::uint32_t flags = 0;
    if (l.brickLights) flags |= shared::REFERENCE_BRICK_LIGHTS;
    if (l.referenceFilter == lighting::ReferenceFilter::PixelCentre)
        flags |= shared::REFERENCE_PIXEL_CENTRE;
    if (!l.referenceMis) flags |= shared::REFERENCE_LIGHT_SAMPLING_ONLY;
    if (l.referenceProbe == lighting::ReferenceProbe::EmitterShape)
        flags |= shared::REFERENCE_PROBE_EMITTER_SHAPE;
    if (l.referenceProbe == lighting::ReferenceProbe::EmitterPower)
        flags |= shared::REFERENCE_PROBE_EMITTER_POWER;
    shared::ReferenceParams p{};
    p.samples = l.samplesPerFrame;
    p.bounces = l.bounces;
    p.flags = flags;
    p.seed = l.seed;
    return p;
}

}  // namespace engine::render
