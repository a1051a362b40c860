#include "world/generators.h"

#include <algorithm>
#include <cmath>

#include "core/hash.h"
#include "world/world_edits.h"

namespace engine::world {

namespace {

float latticeValue(int x, int z, std::uint32_t seed) {
    std::uint32_t h = hashCombine(hashCombine(seed, static_cast<std::uint32_t>(x)), static_cast<std::uint32_t>(z));
    return static_cast<float>(h) * (1.0f / 4294967296.0f);
}

// Smoothly interpolated value noise in [0, 1).
float valueNoise(float x, float z, std::uint32_t seed) {
    float fx = std::floor(x), fz = std::floor(z);
    int ix = static_cast<int>(fx), iz = static_cast<int>(fz);
    float tx = x - fx, tz = z - fz;
    tx = tx * tx * (3.0f - 2.0f * tx);
    tz = tz * tz * (3.0f - 2.0f * tz);
    float a = latticeValue(ix, iz, seed), b = latticeValue(ix + 1, iz, seed);
    float c = latticeValue(ix, iz + 1, seed), d = latticeValue(ix + 1, iz + 1, seed);
    return glm::mix(glm::mix(a, b, tx), glm::mix(c, d, tx), tz);
}

}  // namespace

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

void generateTerrain(BrickGrid& grid, const TerrainParams& p) {
    const glm::ivec3 cells = grid.sizeInCells();
    std::array<int, 64> heights{};
    for (int cz = 0; cz < cells.z; ++cz) {
        for (int cx = 0; cx < cells.x; ++cx) {
            int minH = 1 << 30, maxH = 0;
            for (int z = 0; z < 8; ++z)
                for (int x = 0; x < 8; ++x) {
                    int h = terrainHeight(p, cx * 8 + x, cz * 8 + z);
                    heights[x + 8 * z] = h;
                    minH = std::min(minH, h);
                    maxH = std::max(maxH, h);
                }
            for (int cy = 0; cy < cells.y; ++cy) {
                int y0 = cy * 8;
                if (y0 >= maxH) break;
                glm::ivec3 c{cx, cy, cz};
                if (y0 + 8 <= minH - 1 - p.soilDepth) {
                    grid.writeCellUniform(c, p.rock);
                    continue;
                }
                BrickVoxels voxels{};
                for (int z = 0; z < 8; ++z)
                    for (int x = 0; x < 8; ++x) {
                        int h = heights[x + 8 * z];
                        for (int y = 0; y < 8; ++y) {
                            int wy = y0 + y;
                            MaterialId m = kEmpty;
                            if (wy == h - 1) m = p.top;
                            else if (wy < h - 1 && wy >= h - 1 - p.soilDepth) m = p.soil;
                            else if (wy < h - 1) m = p.rock;
                            voxels[brickVoxelIndex({x, y, z})] = m;
                        }
                    }
                grid.writeCell(c, voxels);
            }
        }
    }
}

void generateCornellBox(BrickGrid& grid, const CornellParams& p) {
    const glm::ivec3 o = p.origin;
    const int n = p.interior, w = p.wall;
    const int outer = n + 2 * w;
    auto box = [&](glm::ivec3 lo, glm::ivec3 hi, MaterialId m) { fillBox(grid, Box{o + lo, o + hi}, m); };
    box({0, 0, 0}, {outer, w, outer}, p.white);              // floor
    box({0, outer - w, 0}, {outer, outer, outer}, p.white);  // ceiling
    box({0, 0, outer - w}, {outer, outer, outer}, p.white);  // back wall
    box({0, 0, 0}, {w, outer, outer}, p.green);              // right as seen from the opening
    box({outer - w, 0, 0}, {outer, outer, outer}, p.red);    // left as seen from the opening
    // Two blocks, as in the classic box but axis-aligned (all faces stay axis-aligned here).
    box({w + n * 15 / 64, w, w + n * 35 / 64}, {w + n * 35 / 64, w + n * 40 / 64, w + n * 55 / 64}, p.white);
    box({w + n * 37 / 64, w, w + n * 12 / 64}, {w + n * 55 / 64, w + n * 20 / 64, w + n * 30 / 64}, p.white);
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
        int sx = rng.uniformInt(p.minSize.x, p.maxSize.x), sz = rng.uniformInt(p.minSize.y, p.maxSize.y);
        int h = rng.uniformInt(p.minHeight, p.maxHeight);
        int x0 = rng.uniformInt(p.margin, std::max(p.margin, size.x - p.margin - sx));
        int z0 = rng.uniformInt(p.margin, std::max(p.margin, size.z - p.margin - sz));
        int ground = 0;
        for (int z = z0; z < z0 + sz; z += 2)
            for (int x = x0; x < x0 + sx; x += 2) ground = std::max(ground, groundHeight(grid, x, z));
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
        int x = rng.uniformInt(p.margin, size.x - 1 - p.margin);
        int z = rng.uniformInt(p.margin, size.z - 1 - p.margin);
        int ground = groundHeight(grid, x, z);
        int top = std::min(ground + p.postHeight, size.y - p.lampSize);
        fillBox(grid, Box{{x, ground, z}, {x + 1, top, z + 1}}, p.post);
        int half = p.lampSize / 2;
        fillBox(grid, Box{{x - half, top, z - half}, {x - half + p.lampSize, top + p.lampSize, z - half + p.lampSize}},
                p.light);
    }
}

}  // namespace engine::world
