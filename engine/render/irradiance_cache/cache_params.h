// The irradiance cache passes' parameters: the one place that fills shared::CacheParams
// (shaders/shared/irradiance_cache.h), from the cache's settings and this frame's bookkeeping.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "lighting/irradiance_cache_settings.h"
#include "shared/irradiance_cache.h"

namespace engine::render {

// What the host's directory decided for this frame.
struct CacheFrame {
    std::uint32_t updates = 0;        // entries in the update list
    std::uint32_t staticUpdates = 0;  // of them, static ones (they come first)
    std::uint32_t traces = 0;         // static entries tracing their K rays
    std::uint32_t buckets = 0;        // hash table buckets (a power of two)
    std::uint32_t capacity = 0;       // slots the GPU buffers hold
    std::uint32_t frameIndex = 0;
    std::uint32_t seed = 0;  // the lighting seed
    glm::uvec2 image{0};
    double timeSeconds = 0.0;
};

shared::CacheParams cacheParams(const lighting::IrradianceCacheSettings& settings,
                                const CacheFrame& frame);

}  // namespace engine::render
