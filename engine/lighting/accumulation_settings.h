// Knobs of temporal accumulation (render/accumulation/): the running mean of the lit image over
// the frames in which nothing the image depends on changed, so a resting camera sees noise fade.
#pragma once

#include <cstdint>

namespace engine::lighting {

struct AccumulationSettings {
    bool enabled = false;
    // Past this many frames the mean turns into an exponential average with weight 1/frames:
    // what changes without a restart (an animated light's colour) still shows, `frames` behind.
    std::uint32_t frames = 256;

    bool operator==(const AccumulationSettings&) const = default;
};

}  // namespace engine::lighting
