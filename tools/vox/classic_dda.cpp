#include "classic_dda.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vox {

using engine::world::BrickGrid;
using engine::world::RayHit;

namespace {
inline int minAxis(glm::vec3 t) { return t.x < t.y ? (t.x < t.z ? 0 : 2) : (t.y < t.z ? 1 : 2); }
}  // namespace

RayHit traceClassicTwoLevel(const BrickGrid& grid, const engine::world::Ray& ray) {
    const glm::vec3 o = ray.origin, d = ray.direction;
    const glm::ivec3 size = grid.sizeInVoxels();
    const glm::ivec3 cellsSize = grid.sizeInCells();
    constexpr float kInf = std::numeric_limits<float>::infinity();
    glm::vec3 inv;
    float tEnter = 0.0f, tExit = ray.tMax;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) {
            if (o[a] < 0.0f || o[a] >= float(size[a])) return {};
            inv[a] = kInf;
            continue;
        }
        inv[a] = 1.0f / d[a];
        float t0 = (0.0f - o[a]) * inv[a], t1 = (float(size[a]) - o[a]) * inv[a];
        tEnter = std::max(tEnter, std::min(t0, t1));
        tExit = std::min(tExit, std::max(t0, t1));
    }
    if (tEnter > tExit) return {};
    const glm::ivec3 step(d.x > 0 ? 1 : -1, d.y > 0 ? 1 : -1, d.z > 0 ? 1 : -1);
    const glm::vec3 absInv = glm::abs(inv);

    glm::vec3 p = o + d * tEnter;
    glm::ivec3 cell = glm::clamp(glm::ivec3(glm::floor(p)) >> 3, glm::ivec3(0), cellsSize - 1);
    glm::vec3 tMaxC, tDeltaC = absInv * 8.0f;
    for (int a = 0; a < 3; ++a)
        tMaxC[a] = d[a] == 0.0f ? kInf : (float((cell[a] + (step[a] > 0)) * 8) - o[a]) * inv[a];
    float tCell = tEnter;
    std::uint32_t steps = 0;
    for (;;) {
        ++steps;
        std::uint32_t c = grid.cell(cell);
        if (c != 0) {
            glm::vec3 q = o + d * tCell;
            glm::ivec3 lo = cell * 8;
            glm::ivec3 v = glm::clamp(glm::ivec3(glm::floor(q)), lo, lo + 7);
            if (c & shared::CELL_HOMOGENEOUS)
                return RayHit{true, v, 0, tCell, engine::world::MaterialId(c & 0xFFFF), steps};
            const engine::world::BrickMask& mask = grid.brickMask(BrickGrid::cellBrick(c));
            glm::vec3 tMaxV, tDeltaV = absInv;
            for (int a = 0; a < 3; ++a)
                tMaxV[a] = d[a] == 0.0f ? kInf : (float(v[a] + (step[a] > 0)) - o[a]) * inv[a];
            float t = tCell;
            for (;;) {
                ++steps;
                glm::ivec3 local = v - lo;
                int bit = local.x + 8 * local.y + 64 * local.z;
                if ((mask.words[bit >> 5] >> (bit & 31)) & 1u)
                    return RayHit{true, v, 0, t, grid.brickVoxels(BrickGrid::cellBrick(c))[bit],
                                  steps};
                int a = minAxis(tMaxV);
                t = tMaxV[a];
                v[a] += step[a];
                tMaxV[a] += tDeltaV[a];
                if (unsigned(v[a] - lo[a]) > 7u) break;
            }
        }
        int a = minAxis(tMaxC);
        tCell = tMaxC[a];
        if (tCell > tExit) return RayHit{false, {}, 0, 0.0f, 0, steps};
        cell[a] += step[a];
        tMaxC[a] += tDeltaC[a];
        if (unsigned(cell[a]) >= unsigned(cellsSize[a]))
            return RayHit{false, {}, 0, 0.0f, 0, steps};
    }
}

}  // namespace vox
