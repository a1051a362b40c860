// Restir: Voxel ReSTIR's direct light (thesis §4; `--method restir`, and RIS, its first pass
// alone). Owns the parameters and the reservoirs: this frame's candidates, each pixel's own
// reservoir after temporal reuse, and the final reservoirs, ping-ponged so temporal reuse reads
// last frame's. Each frame: candidates -> temporal reuse (with a history) -> spatial reuse ->
// shade, or for RIS candidates -> shade.
#pragma once

#include <cstdint>
#include <string>

#include "gpu/buffer.h"
#include "render/restir/restir_initial_pass.h"
#include "render/restir/restir_shade_pass.h"
#include "render/restir/restir_spatial_pass.h"
#include "render/restir/restir_temporal_pass.h"
#include "render/technique.h"

namespace engine::render {

class Restir : public Technique {
public:
    explicit Restir(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;

private:
    gpu::Context& mCtx;
    RestirInitialPass mInitial;
    RestirTemporalPass mTemporal;
    RestirSpatialPass mSpatial;
    RestirShadePass mShade;
    gpu::Buffer mParams, mCandidates, mOwn, mFinal[2];
    glm::uvec2 mSize{0};
    bool mTemporalReuse = false;  // this frame: temporal reuse of last frame's final reservoirs
    bool mSpatialReuse = false;
};

}  // namespace engine::render
