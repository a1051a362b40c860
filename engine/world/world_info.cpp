#include "world/world_info.h"

#include <fmt/format.h>

namespace engine::world {

namespace {
std::string bytes(std::size_t b) {
    if (b >= (1u << 20)) return fmt::format("{:.2f} MiB", double(b) / (1 << 20));
    if (b >= (1u << 10)) return fmt::format("{:.1f} KiB", double(b) / (1 << 10));
    return fmt::format("{} B", b);
}
}  // namespace

WorldInfo describeWorld(const Scene& scene) {
    const BrickGrid& g = scene.grid;
    WorldInfo info;
    info.sizeInVoxels = g.sizeInVoxels();
    info.sizeInCells = g.sizeInCells();
    info.cells = g.cellCount();
    std::size_t occupied = 0;
    g.topGrid().forEachLiveCell([&](std::uint32_t c) { occupied += (c != shared::CELL_EMPTY); });
    info.emptyCells = info.cells - occupied;
    info.homogeneousCells = g.homogeneousCells();
    info.bricks = g.liveBricks();
    info.freeBricks = g.brickCapacity() - g.liveBricks();
    info.solidVoxels = g.solidVoxels();
    info.emissiveVoxels = scene.emissiveVoxels();
    info.materials = scene.palette.size() - 1;
    GridMemory m = g.memory();
    info.topGridBytes = m.topGridBytes;
    info.superGridBytes = m.superGridBytes;
    info.brickPoolBytes = m.brickPoolBytes;
    info.bookkeepingBytes = m.bookkeepingBytes;
    info.paletteBytes = scene.palette.gpuBytes();
    return info;
}

std::string formatWorldInfo(const WorldInfo& i, const std::string& title) {
    std::string s;
    s += fmt::format("world        {}\n", title);
    s += fmt::format("size         {} x {} x {} voxels ({} x {} x {} cells of 8^3)\n",
                     i.sizeInVoxels.x, i.sizeInVoxels.y, i.sizeInVoxels.z, i.sizeInCells.x,
                     i.sizeInCells.y, i.sizeInCells.z);
    s += fmt::format("cells        {} total: {} empty, {} homogeneous (no storage), {} bricks\n",
                     i.cells, i.emptyCells, i.homogeneousCells, i.bricks);
    s += fmt::format("brick pool   {} live bricks, {} free for reuse\n", i.bricks, i.freeBricks);
    s += fmt::format("voxels       {} solid, {} emissive\n", i.solidVoxels, i.emissiveVoxels);
    s += fmt::format("materials    {}\n", i.materials);
    s += "memory\n";
    s += fmt::format("  top grid     {:>12}  ({} bytes)\n", bytes(i.topGridBytes), i.topGridBytes);
    s += fmt::format("  super grid   {:>12}  ({} bytes: skip distance and count per 4^3 cells)\n",
                     bytes(i.superGridBytes), i.superGridBytes);
    s += fmt::format("  brick pool   {:>12}  ({} bytes: 1024 voxel + 80 mask bytes per brick)\n",
                     bytes(i.brickPoolBytes), i.brickPoolBytes);
    s += fmt::format("  palette      {:>12}  ({} bytes)\n", bytes(i.paletteBytes), i.paletteBytes);
    s += fmt::format("  bookkeeping  {:>12}  ({} bytes: free list, dirty flags)\n",
                     bytes(i.bookkeepingBytes), i.bookkeepingBytes);
    s +=
        fmt::format("  total        {:>12}  ({} bytes; a dense uint16 grid would take {})\n",
                    bytes(i.totalBytes()), i.totalBytes(),
                    bytes(std::size_t(i.sizeInVoxels.x) * i.sizeInVoxels.y * i.sizeInVoxels.z * 2));
    return s;
}

std::string worldInfoJson(const WorldInfo& i) {
    return fmt::format(
        "{{\"size\": [{}, {}, {}], \"cells\": {}, \"empty_cells\": {}, \"homogeneous_cells\": {}, "
        "\"bricks\": {}, "
        "\"free_bricks\": {}, \"solid_voxels\": {}, \"emissive_voxels\": {}, \"materials\": {}, "
        "\"bytes\": {{\"top_grid\": {}, \"super_grid\": {}, \"brick_pool\": {}, \"palette\": {}, "
        "\"bookkeeping\": {}, \"total\": {}}}}}",
        i.sizeInVoxels.x, i.sizeInVoxels.y, i.sizeInVoxels.z, i.cells, i.emptyCells,
        i.homogeneousCells, i.bricks, i.freeBricks, i.solidVoxels, i.emissiveVoxels, i.materials,
        i.topGridBytes, i.superGridBytes, i.brickPoolBytes, i.paletteBytes, i.bookkeepingBytes,
        i.totalBytes());
}

}  // namespace engine::world
