#include "render/regir/regir_grid.h"

#include <algorithm>

#include "gpu/command_list.h"
#include "gpu/uploader.h"
#include "render/frame_commands.h"
#include "shared/shader_features.h"

namespace engine::render {

shared::RegirGridInfo regirGridFor(glm::ivec3 worldVoxels, const shared::RegirKnobs& knobs) {
    const glm::vec3 world = glm::max(glm::vec3(worldVoxels), glm::vec3(1.0f));
    float size = std::max(knobs.cellSize, 1.0f);
    glm::uvec3 dims;
    for (;;) {
        dims = glm::uvec3(glm::ceil(world / size));
        if (std::uint64_t(dims.x) * dims.y * dims.z <= shared::REGIR_MAX_CELLS) break;
        size = std::ceil(size * 1.1f);
    }
    shared::RegirGridInfo g{};
    g.origin = glm::vec4(0.0f, 0.0f, 0.0f, size);
    g.dims = glm::uvec4(dims, dims.x * dims.y * dims.z);
    g.build = glm::uvec4(std::max(knobs.buildCandidates, 1u), 0u, 0u, 0u);
    return g;
}

RegirGrid::RegirGrid(gpu::Context& ctx)
    : mCtx(ctx),
      mMark(ctx, "regir.mark", "regir/mark_cells", 4),
      mBuild(ctx, "regir.build", "regir/build_cells", 4) {}

std::uint64_t RegirGrid::deviceBytes(glm::ivec3 worldVoxels, const shared::RegirKnobs& knobs) {
    const std::uint64_t cells = regirGridFor(worldVoxels, knobs).dims.w;
    return sizeof(shared::RegirGridInfo) +
           cells * shared::REGIR_CELL_ENTRIES * sizeof(shared::RegirEntry) +
           cells * sizeof(std::uint32_t);
}

TechniquePlan RegirGrid::plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2) {
    TechniquePlan p;
    p.runs = lighting::usesRegir(l);
    p.deviceBytes = deviceBytes(scene.sizeInVoxels, l.regir);
    p.features = {{FEATURE_REGIR, 1u}};
    return p;
}

void RegirGrid::prepare(const FrameChanges&, const FrameInput& in, gpu::Uploader& uploader,
                        shared::FrameParams& params) {
    mInfo = regirGridFor(in.scene.grid.sizeInVoxels(), in.lighting.regir);
    mInfo.build.y = in.frameIndex;
    mInfo.build.z = in.lighting.seed;
    const std::uint64_t cells = mInfo.dims.w;
    const std::uint64_t gridBytes = sizeof(shared::RegirGridInfo) +
                                    cells * shared::REGIR_CELL_ENTRIES * sizeof(shared::RegirEntry);
    // Grown to the largest world seen, never to a fixed worst case.
    if (!mGrid.valid() || mGrid.size() < gridBytes) {
        mGrid = gpu::Buffer(mCtx, gpu::BufferKind::Storage, gridBytes, "regir.grid");
        mMarks = gpu::Buffer(mCtx, gpu::BufferKind::Storage, cells * sizeof(std::uint32_t),
                             "regir.marks");
    }
    uploader.write(mGrid, 0, &mInfo, sizeof(mInfo));
    const std::uint64_t address = mGrid.deviceAddress();
    params.regirGrid = glm::uvec4(std::uint32_t(address), std::uint32_t(address >> 32), 0u, 0u);
}

void RegirGrid::record(FrameCommands& commands, const FrameBuffers& frame) {
    gpu::CommandList& cmd = commands.current();
    cmd.fillBuffer(mMarks, 0);
    const PassBinding own[] = {{shared::REGIR_BINDING_FRAME, &frame.frameParams},
                               {shared::REGIR_BINDING_GBUFFER, &frame.gbuffer},
                               {shared::REGIR_BINDING_MARKS, &mMarks},
                               {shared::REGIR_BINDING_GRID, &mGrid}};
    mMark.record(cmd, frame.scene, own, screenGroups(frame.size));
    const std::uint32_t threads = mInfo.dims.w * shared::REGIR_CELL_ENTRIES;
    mBuild.record(
        cmd, frame.scene, own,
        glm::uvec2((threads + shared::REGIR_GROUP_SIZE - 1) / shared::REGIR_GROUP_SIZE, 1u));
    // The candidates read the grid by address, which declares no binding: wait here.
    cmd.barrier();
}

}  // namespace engine::render
