// ReGIR, world-space light candidates (Boksansky et al., Ray Tracing Gems II ch. 23; RTXDI's
// ReGIR): a grid of cells over the world, each holding REGIR_CELL_ENTRIES lights resampled every
// frame from power-drawn candidates with a target that favours lights near the cell and turned
// towards it (layout: shaders/shared/regir.h). ReSTIR's and RIS's candidates draw entries of the
// cell their surface lies in (shaders/restir/initial_candidates.comp) and find the grid through
// FrameParams::regirGrid, a device address.
//
// Two passes per frame: "regir.mark" marks the cells this frame's G-buffer surfaces lie in and
// "regir.build" fills only those, so the cost follows the view. The grid spans the world (cell
// size from the knob, grown until the world fits in REGIR_MAX_CELLS), so its memory follows the
// world. It keeps nothing between frames: an edit of the lights changes the emitter list and its
// alias table (incremental, render/gpu_emitter_list.h) and the next frame's build sees it.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "gpu/buffer.h"
#include "render/passes/lit_pass.h"
#include "render/technique.h"
#include "shared/regir.h"

namespace engine::render {

// The grid over a world of `worldVoxels`: cells of at least `cellSize` voxels, as few more as
// keep the count within REGIR_MAX_CELLS.
shared::RegirGridInfo regirGridFor(glm::ivec3 worldVoxels, const shared::RegirKnobs& knobs);

// Runs for ReSTIR and RIS with sampling regir (lighting::usesRegir).
class RegirGrid : public Technique {
public:
    explicit RegirGrid(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    // Sampling regir is part of ReSTIR's and RIS's description.
    static std::string describe(const lighting::LightingSettings&) { return ""; }
    // The grid and its marks over a world of `worldVoxels`.
    static std::uint64_t deviceBytes(glm::ivec3 worldVoxels, const shared::RegirKnobs& knobs);

    // Sizes the grid for the world, queues this frame's header (grid, candidates, randomness) and
    // sets FrameParams::regirGrid.
    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    // Clears the marks, then the two passes; after the G-buffer and before the candidates.
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    const shared::RegirGridInfo& info() const { return mInfo; }
    // The grid buffer (RegirGridInfo, then RegirEntry per cell x entry), for tests.
    const gpu::Buffer& grid() const { return mGrid; }

private:
    gpu::Context& mCtx;
    LitPass mMark, mBuild;
    gpu::Buffer mGrid, mMarks;
    shared::RegirGridInfo mInfo{};
};

}  // namespace engine::render
