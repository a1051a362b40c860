// Knobs of voxel cone tracing (`--indirect vct`, render/vct/): a camera-centred radiance
// clipmap injected from direct light each frame, gathered per pixel by six diffuse cones — the
// cheap, leaky indirect method set against the irradiance cache and the path tracer.
#pragma once

#include <cstdint>

namespace engine::lighting {

struct VctSettings {
    std::uint32_t levels = 4;  // clipmap levels of 32^3 texels, 2, 4, 8, 16 voxels wide (1..4)
    bool leakMitigation =
        true;  // directional texels + cone start offset (off: isotropic, from the surface)
    float startOffset =
        1.0f;  // cone start along the normal, in level-0 texels (2 voxels), with mitigation
    bool extraBounce = false;  // inject a second bounce from the last frame's volume
    // Texels that stay in the clipmap are re-injected every this many frames, in turn (new ones,
    // those near dynamic objects and every texel after an edit or a light change at once).
    std::uint32_t refreshPeriod = 8;
    // vct.classify visits every texel of every level each frame, not only the blocks that may
    // have changed (render/vct/vct_block_list.h): the same image, the cost before issue 38's
    // block list — for tests and timing.
    bool classifyAll = false;

    bool operator==(const VctSettings&) const = default;
};

}  // namespace engine::lighting
