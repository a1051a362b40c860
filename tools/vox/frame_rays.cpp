#include "frame_rays.h"

#include <algorithm>

#include "shared/brick_grid.h"

namespace vox {

std::uint64_t rayBound(const engine::lighting::LightingSettings& l,
                       const engine::world::Scene& scene, const engine::render::FrameResult& r,
                       std::uint64_t pixels, std::uint64_t surface) {
    using engine::lighting::Method;
    const std::uint64_t sun =
        glm::any(glm::greaterThan(scene.sky.sunRadiance, glm::vec3(0.0f))) ? 1 : 0;
    std::uint64_t perSurface = 0;
    switch (l.method) {
        case Method::Preview:
            perSurface = sun;
            break;  // counted on the GPU instead; for completeness
        case Method::Restir:
            // initial candidates (the chosen one's visibility), the unbiased mode's visibility
            // test from last frame's surface (only where it moved; spatial reuse traces none),
            // shading: sun + chosen light.
            perSurface = (l.restir.candidateVisibility ? 1 : 0) +
                         (l.restir.unbiased && l.restir.temporal ? 1 : 0) + sun + 1;
            break;
        case Method::Ris:
            perSurface = sun + 1;
            break;
        case Method::Uniform:
            perSurface = sun + l.shadowRays;
            break;
        case Method::BruteForce:
            perSurface = sun + r.emitters;
            break;
        case Method::Reference:
            // per sample: at each of up to bounces + 1 vertices the sun and one emitter shadow
            // ray, and a cosine ray per bounce, plus one from the last vertex with MIS (Russian
            // roulette and escapes end paths early)
            perSurface = std::uint64_t(std::max(l.samplesPerFrame, 1u)) *
                         ((l.bounces + 1) * (sun + 1) + l.bounces +
                          (l.bounces > 0 && l.referenceMis ? 1 : 0));
            break;
    }
    // The reference traces its own camera ray per sample (its box filter), besides the G-buffer's.
    const std::uint64_t referenceCameraRays =
        l.method == Method::Reference ? pixels * std::uint64_t(std::max(l.samplesPerFrame, 1u)) : 0;
    return pixels + referenceCameraRays + surface * perSurface + (r.cacheUsed ? r.cache.rays : 0);
}

std::uint64_t surfacePixels(const engine::render::FrameImages& images) {
    std::uint64_t n = 0;
    for (const auto& g : images.gbuffer) n += std::uint32_t(g.voxel.w) != shared::FACE_NONE;
    return n;
}

}  // namespace vox
