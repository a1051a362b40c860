#include "world/generators.h"

#include <algorithm>
#include <cmath>

#include "core/hash.h"
#include "core/progress.h"
#include "world/height_field.h"
#include "world/value_noise.h"
#include "world/world_edits.h"

namespace engine::world {

int terrainHeight(const TerrainParams& p, int x, int z) {
    float sum = 0.0f, norm = 0.0f, amp = 1.0f, freq = 1.0f / std::max(p.wavelength, 1.0f);
    for (int o = 0; o < std::max(p.octaves, 1); ++o) {
        sum += amp * valueNoise(x * freq, z * freq, p.seed + 977u * o);
        norm += amp;
        amp *= 0.5f;
        freq *= 2.0f;
    }
    float h = p.baseHeight + p.amplitude * (2.0f * sum / norm - 1.0f);
    return std::max(1, static_cast<int>(std::floor(h)));
}

ColumnMaterials terrainColumns(const TerrainParams& p) {
    ColumnMaterials m;
    m.top = p.top;
    m.soil = p.soil;
    m.rock = p.rock;
    m.soilDepth = p.soilDepth;
    return m;
}

void generateTerrain(BrickGrid& grid, const TerrainParams& p) {
    fillHeightField(
        grid, [&](int x, int z) { return terrainHeight(p, x, z); }, terrainColumns(p));
}

void generateCornellBox(BrickGrid& grid, const CornellParams& p) {
    const glm::ivec3 o = p.origin;
    const int n = p.interior, w = p.wall;
    const int outer = n + 2 * w;
    auto box = [&](glm::ivec3 lo, glm::ivec3 hi, MaterialId m) {
        fillBox(grid, Box{o + lo, o + hi}, m);
    };
    box({0, 0, 0}, {outer, w, outer}, p.white);              // floor
    box({0, outer - w, 0}, {outer, outer, outer}, p.white);  // ceiling
    box({0, 0, outer - w}, {outer, outer, outer}, p.white);  // back wall
    box({0, 0, 0}, {w, outer, outer}, p.green);              // right as seen from the opening
    box({outer - w, 0, 0}, {outer, outer, outer}, p.red);    // left as seen from the opening
    // Two blocks, as in the classic box but axis-aligned (all faces stay axis-aligned here).
    box({w + n * 15 / 64, w, w + n * 35 / 64}, {w + n * 35 / 64, w + n * 40 / 64, w + n * 55 / 64},
        p.white);
    box({w + n * 37 / 64, w, w + n * 12 / 64}, {w + n * 55 / 64, w + n * 20 / 64, w + n * 30 / 64},
        p.white);
    // Ceiling light: brick-aligned so each 8^3 is a homogeneous emissive cell (a brick light).
    int span = p.lightBricks * 8;
    int start = ((w + (n - span) / 2) / 8) * 8;
    int y = ((outer - w - 8) / 8) * 8;
    box({start, y, start}, {start + span, y + 8, start + span}, p.light);
}

int groundHeight(const BrickGrid& grid, int x, int z) {
    for (int y = grid.sizeInVoxels().y - 1; y >= 0; --y) {
        if (grid.get({x, y, z}) != kEmpty) return y + 1;
    }
    return 0;
}

void generateBuildings(BrickGrid& grid, const BuildingsParams& p) {
    Rng rng(p.seed);
    const glm::ivec3 size = grid.sizeInVoxels();
    for (int i = 0; i < p.count; ++i) {
        int sx = rng.uniformInt(p.minSize.x, p.maxSize.x),
            sz = rng.uniformInt(p.minSize.y, p.maxSize.y);
        int h = rng.uniformInt(p.minHeight, p.maxHeight);
        int x0 = rng.uniformInt(p.margin, std::max(p.margin, size.x - p.margin - sx));
        int z0 = rng.uniformInt(p.margin, std::max(p.margin, size.z - p.margin - sz));
        int ground = 0;
        for (int z = z0; z < z0 + sz; z += 2)
            for (int x = x0; x < x0 + sx; x += 2)
                ground = std::max(ground, groundHeight(grid, x, z));
        int top = std::min(ground + h, size.y - 2);
        glm::ivec3 lo{x0, std::max(ground - 3, 0), z0}, hi{x0 + sx, top, z0 + sz};
        fillBox(grid, Box{lo, hi}, p.wall);
        fillBox(grid, Box{lo + glm::ivec3(1, 4, 1), hi - glm::ivec3(1, 1, 1)}, kEmpty);
        fillBox(grid, Box{{lo.x - 1, top, lo.z - 1}, {hi.x + 1, top + 1, hi.z + 1}}, p.roof);
        // Window rows on all four walls, every fourth voxel, every fifth storey line.
        for (int y = ground + 3; y + 2 < top; y += 5) {
            for (int x = x0 + 2; x + 2 < x0 + sx; x += 4) {
                fillBox(grid, Box{{x, y, z0}, {x + 2, y + 2, z0 + 1}}, p.window);
                fillBox(grid, Box{{x, y, z0 + sz - 1}, {x + 2, y + 2, z0 + sz}}, p.window);
            }
            for (int z = z0 + 2; z + 2 < z0 + sz; z += 4) {
                fillBox(grid, Box{{x0, y, z}, {x0 + 1, y + 2, z + 2}}, p.window);
                fillBox(grid, Box{{x0 + sx - 1, y, z}, {x0 + sx, y + 2, z + 2}}, p.window);
            }
        }
        int door = x0 + sx / 2 - 1;
        fillBox(grid, Box{{door, ground, z0}, {door + 3, ground + 5, z0 + 1}}, kEmpty);
    }
}

void generateLamps(BrickGrid& grid, const LampsParams& p) {
    Rng rng(p.seed);
    const glm::ivec3 size = grid.sizeInVoxels();
    for (int i = 0; i < p.count; ++i) {
        if ((i & 4095) == 0)
            reportProgress("generating lamps", std::uint64_t(i), std::uint64_t(p.count));
        int x = rng.uniformInt(p.margin, size.x - 1 - p.margin);
        int z = rng.uniformInt(p.margin, size.z - 1 - p.margin);
        int ground = groundHeight(grid, x, z);
        int top = std::min(ground + p.postHeight, size.y - p.lampSize);
        fillBox(grid, Box{{x, ground, z}, {x + 1, top, z + 1}}, p.post);
        int half = p.lampSize / 2;
        fillBox(grid,
                Box{{x - half, top, z - half},
                    {x - half + p.lampSize, top + p.lampSize, z - half + p.lampSize}},
                p.light);
    }
    reportProgress("generating lamps", std::uint64_t(p.count), std::uint64_t(p.count));
}

}  // namespace engine::world
