// Presampled light tiles (Wyman & Panteleev 2021; RTXDI's presampled light sets): one small pass
// per frame draws LIGHT_TILE_COUNT x LIGHT_TILE_SIZE emitters by power into a buffer with each
// one's data and probability (layout: shaders/shared/light_tiles.h). ReSTIR's candidates read
// consecutive entries of a random tile and the irradiance cache's light bounce one random entry
// (shaders/light_tiles/light_tiles.glsl), instead of drawing from the alias table and fetching
// the emitter per sample. The consumers find the buffer through FrameParams::lightTiles (a device
// address), so no pass needs a binding of its own for it.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "lighting/lighting_settings.h"
#include "render/passes/lit_pass.h"

namespace engine::gpu {
class CommandList;
class Uploader;
}  // namespace engine::gpu

namespace engine::render {

// Does a frame lit with `l` read the tiles? With the light_tiles knob on and lights drawn by power:
// ReSTIR/RIS candidates and the irradiance cache's light bounce (which otherwise draws from the
// alias table, as does everything when the knob is off).
bool lightTilesUsed(const lighting::LightingSettings& l);

class LightTiles {
public:
    explicit LightTiles(gpu::Context& ctx);

    // Queues this frame's randomness (the lighting seed and the frame index, as every pass).
    void writeParams(gpu::Uploader& uploader, std::uint32_t frameIndex, std::uint32_t seed);
    // The presample pass, "light_tiles"; record it after the emitter list's upload and before the
    // passes that read the tiles.
    void record(gpu::CommandList& cmd, const SceneBindings& scene);
    // FrameParams::lightTiles for a frame that draws the tiles.
    glm::uvec4 frameField() const;
    // The last drawn tiles (LightTileSample per entry), for tests.
    const gpu::Buffer& samples() const { return mSamples; }

private:
    LitPass mPass;
    gpu::Buffer mParams, mSamples;
};

}  // namespace engine::render
