// Knobs of the path-traced indirect term (`--indirect path`, render/path_indirect/): bounce paths
// from the G-buffer's surfaces, the real-time path tracer the irradiance cache is compared with.
#pragma once

#include <cstdint>

namespace engine::lighting {

struct PathIndirectSettings {
    std::uint32_t samples = 1;  // cosine-sampled paths per pixel per frame
    std::uint32_t bounces = 1;  // bounces per path: 1 = one bounce, as the cache's default
    bool accumulate = true;     // average over frames while camera and world stay still

    bool operator==(const PathIndirectSettings&) const = default;
};

}  // namespace engine::lighting
