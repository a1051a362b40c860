#include "render/regir/regir_grid.h"

#include <algorithm>

#include "gpu/command_list.h"
#include "gpu/uploader.h"

namespace engine::render {

bool regirUsed(const lighting::LightingSettings& l) {
    using lighting::Method;
    return l.regir.enabled != 0u && (l.method == Method::Restir || l.method == Method::Ris);
}

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
    : mCtx(ctx), mMark(ctx, "regir.mark", "regir/mark_cells", 4), mBuild(ctx, "regir.build", "regir/build_cells", 4) {}

void RegirGrid::prepare(gpu::Uploader& uploader, glm::ivec3 worldVoxels, const shared::RegirKnobs& knobs,
                        std::uint32_t frameIndex, std::uint32_t seed) {
    mInfo = regirGridFor(worldVoxels, knobs);
    mInfo.build.y = frameIndex;
    mInfo.build.z = seed;
    const std::uint64_t cells = mInfo.dims.w;
    const std::uint64_t gridBytes = sizeof(shared::RegirGridInfo) + cells * shared::REGIR_CELL_ENTRIES * sizeof(shared::RegirEntry);
    // Grown to the largest world seen, never to a fixed worst case.
    if (!mGrid.valid() || mGrid.size() < gridBytes) {
        mGrid = gpu::Buffer(mCtx, gpu::BufferKind::Storage, gridBytes, "regir.grid");
        mMarks = gpu::Buffer(mCtx, gpu::BufferKind::Storage, cells * sizeof(std::uint32_t), "regir.marks");
    }
    uploader.write(mGrid, 0, &mInfo, sizeof(mInfo));
}

void RegirGrid::record(gpu::CommandList& cmd, const SceneBindings& scene, const gpu::Buffer& frameParams,
                       const gpu::Buffer& gbuffer, glm::uvec2 imageSize) {
    cmd.fillBuffer(mMarks, 0);
    cmd.barrier();
    const PassBinding own[] = {{shared::REGIR_BINDING_FRAME, &frameParams},
                               {shared::REGIR_BINDING_GBUFFER, &gbuffer},
                               {shared::REGIR_BINDING_MARKS, &mMarks},
                               {shared::REGIR_BINDING_GRID, &mGrid}};
    mMark.record(cmd, scene, own, screenGroups(imageSize));
    const std::uint32_t threads = mInfo.dims.w * shared::REGIR_CELL_ENTRIES;
    mBuild.record(cmd, scene, own, glm::uvec2((threads + shared::REGIR_GROUP_SIZE - 1) / shared::REGIR_GROUP_SIZE, 1u));
}

glm::uvec4 RegirGrid::frameField() const {
    const std::uint64_t address = mGrid.deviceAddress();
    return glm::uvec4(std::uint32_t(address), std::uint32_t(address >> 32), 0u, 0u);
}

}  // namespace engine::render
