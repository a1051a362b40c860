#include "world/height_field.h"

#include <algorithm>
#include <array>
#include <cstdlib>

#include "core/progress.h"

namespace engine::world {

void fillHeightField(BrickGrid& grid, const std::function<int(int, int)>& heightAt,
                     const ColumnMaterials& m) {
    fillHeightFieldAt(grid, heightAt, m, glm::ivec3(0), true);
}

void fillHeightFieldAt(BrickGrid& grid, const std::function<int(int, int)>& heightAt,
                       const ColumnMaterials& m, glm::ivec3 originCell, bool progress) {
    // Every decision below is made from world coordinates (the grid's cell + originCell), so a
    // cell comes out the same whether the grid is the whole world or one region of it.
    const glm::ivec3 cells = grid.sizeInCells();
    const glm::ivec3 o = originCell * kBrickDim;
    const bool cliffs = m.cliff != kEmpty && m.cliffStep < (1 << 30);
    // Heights of one 8x8 column of cells plus a one-voxel border (for the cliff test).
    std::array<int, 10 * 10> heights{};
    auto h = [&](int x, int z) -> int& { return heights[std::size_t(x + 1 + 10 * (z + 1))]; };
    for (int cz = 0; cz < cells.z; ++cz) {
        if (progress)
            reportProgress("generating height field", std::uint64_t(cz), std::uint64_t(cells.z));
        for (int cx = 0; cx < cells.x; ++cx) {
            int minH = 1 << 30, maxH = 0;
            for (int z = -1; z <= 8; ++z)
                for (int x = -1; x <= 8; ++x) {
                    bool inside = x >= 0 && x < 8 && z >= 0 && z < 8;
                    if (!inside && !cliffs) continue;
                    h(x, z) = heightAt(o.x + cx * 8 + x, o.z + cz * 8 + z);
                    if (!inside) continue;
                    minH = std::min(minH, h(x, z));
                    maxH = std::max(maxH, h(x, z));
                }
            for (int cy = 0; cy < cells.y; ++cy) {
                int y0 = o.y + cy * 8;
                if (y0 >= maxH) break;
                glm::ivec3 c{cx, cy, cz};
                if (y0 + 8 <= minH - 1 - m.soilDepth) {
                    grid.writeCellUniform(c, m.rock);
                    continue;
                }
                BrickVoxels voxels{};
                for (int z = 0; z < 8; ++z)
                    for (int x = 0; x < 8; ++x) {
                        int top = h(x, z);
                        bool cliff = cliffs && (std::abs(top - h(x - 1, z)) > m.cliffStep ||
                                                std::abs(top - h(x + 1, z)) > m.cliffStep ||
                                                std::abs(top - h(x, z - 1)) > m.cliffStep ||
                                                std::abs(top - h(x, z + 1)) > m.cliffStep);
                        MaterialId surface = top - 1 >= m.snowLine && m.snow != kEmpty ? m.snow
                                             : cliff                                   ? m.cliff
                                                                                       : m.top;
                        MaterialId soil = cliff ? m.cliff : m.soil;
                        for (int y = 0; y < 8; ++y) {
                            int wy = y0 + y;
                            MaterialId v = kEmpty;
                            if (wy == top - 1)
                                v = surface;
                            else if (wy < top - 1 && wy >= top - 1 - m.soilDepth)
                                v = soil;
                            else if (wy < top - 1)
                                v = m.rock;
                            voxels[brickVoxelIndex({x, y, z})] = v;
                        }
                    }
                grid.writeCell(c, voxels);
            }
        }
    }
    if (progress)
        reportProgress("generating height field", std::uint64_t(cells.z), std::uint64_t(cells.z));
}

}  // namespace engine::world
