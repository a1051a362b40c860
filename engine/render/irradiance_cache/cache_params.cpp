#include "render/irradiance_cache/cache_params.h"

#include <algorithm>

namespace engine::render {

shared::CacheParams cacheParams(const lighting::IrradianceCacheSettings& s, const CacheFrame& f) {
    shared::CacheParams p{};
    p.updates = f.updates;
    p.traces = f.traces;
    p.directions = s.directions;
    p.raysPerUpdate = s.raysPerUpdate;
    p.frameIndex = f.frameIndex;
    p.bounces = s.bounces;
    p.seed = f.seed;
    p.tableMask = f.buckets - 1u;
    p.capacity = f.capacity;
    p.flags = (s.filter ? 0u : shared::CACHE_FLAG_NO_FILTER) |
              (s.fullRetrace ? shared::CACHE_FLAG_FULL_RETRACE : 0u);
    p.width = f.image.x;
    p.height = f.image.y;
    p.staticUpdates = f.staticUpdates;
    p.alpha = s.alpha;
    p.maxRayLength = std::min(s.maxRayLength, shared::CACHE_MAX_RAY_LENGTH);
    p.time = static_cast<float>(f.timeSeconds);
    p.fadeSeconds = s.fadeSeconds;
    p.lodDistance = s.lodDistance;
    p.fallbackRadius = s.fallbackRadius;
    p.lightSamples = s.lightSamples;
    return p;
}

}  // namespace engine::render
