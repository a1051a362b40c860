// FrameResult: what Renderer::render reports of a frame — GPU time per pass, the uploads, the
// emitter list's update, and each technique's statistics (Technique::collect).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "lighting/emitter_list.h"
#include "render/dvf_sky/dvf_sky.h"
#include "render/gpu_world.h"
#include "render/irradiance_cache/irradiance_cache.h"

namespace engine::render {

struct FrameResult {
    std::vector<std::pair<std::string, double>> passMs;  // GPU milliseconds per pass, in order
    WorldUploadStats upload;
    lighting::EmitterUpdateStats emitterUpdate;
    double emitterUpdateMs = 0.0;  // CPU time of the emitter list update
    double dynamicUpdateMs = 0.0;  // CPU time of posing and re-voxelising dynamic objects
    std::uint32_t emitters = 0;
    bool regirSampling =
        false;  // candidates from ReGIR's grid (--sampling regir, or auto's choice)
    std::uint32_t referenceSamples = 0;   // samples per pixel accumulated so far (reference)
    std::uint32_t accumulatedFrames = 0;  // frames in the lit image's running mean (accumulate)
    bool cacheUsed = false;
    // The cache had no visible set yet: the first submission waited for the G-buffer.
    bool cacheSplitFrame = false;
    double cachePrepareMs = 0.0;  // CPU time of the cache's directory and uploads
    IrradianceCacheStats cache;
    bool skyUsed = false;  // a sky term (DVF or its reference) was added
    DvfSkyStats sky;       // DVF: masks held, queued and traced this frame
    bool vctUsed = false;
    std::uint32_t vctBlocks = 0;  // VCT: blocks of 4^3 texels vct.classify visited (0: no pass)
    double vctPrepareMs = 0.0;    // VCT: CPU time of its prepare (the block list included)
    double totalMs() const;
    double passMsOf(const std::string& name) const;
};

}  // namespace engine::render
