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
#include <string>

#include "gpu/buffer.h"
#include "render/passes/lit_pass.h"
#include "render/technique.h"

namespace engine::render {

// Runs when lights are drawn by power with the light_tiles knob on (lighting::usesLightTiles):
// ReSTIR/RIS candidates and the irradiance cache's light bounce, which otherwise draw from the
// alias table.
class LightTiles : public Technique {
public:
    explicit LightTiles(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings&) { return ""; }
    static std::uint64_t deviceBytes();

    // Queues this frame's randomness (the lighting seed and the frame index, as every pass) and
    // sets FrameParams::lightTiles.
    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    // The presample pass, "light_tiles", before the passes that read the tiles.
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    // The last drawn tiles (LightTileSample per entry), for tests.
    const gpu::Buffer& samples() const { return mSamples; }

private:
    gpu::Context& mCtx;
    LitPass mPass;
    gpu::Buffer mParams, mSamples;
};

}  // namespace engine::render
