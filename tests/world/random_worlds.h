// Random worlds and rays for traversal tests: every kind of cell (empty, homogeneous, sparse and
// dense bricks) and the awkward rays (starting inside solid, on brick borders, axis-parallel,
// from outside the world).
#pragma once

#include <string>
#include <vector>

#include "core/hash.h"
#include "world/ray_traversal.h"
#include "world/world_edits.h"

namespace testing_worlds {

using namespace engine::world;

enum class Kind { Sparse, Dense, Homogeneous, Mixed };

inline const char* kindName(Kind k) {
    switch (k) {
        case Kind::Sparse:
            return "sparse";
        case Kind::Dense:
            return "dense";
        case Kind::Homogeneous:
            return "homogeneous";
        default:
            return "mixed";
    }
}

inline BrickGrid makeWorld(Kind kind, std::uint64_t seed, glm::ivec3 size = {48, 40, 56}) {
    BrickGrid grid(size);
    engine::Rng rng(seed);
    glm::ivec3 s = grid.sizeInVoxels();
    auto randomVoxel = [&] {
        return glm::ivec3(rng.uniformInt(0, s.x - 1), rng.uniformInt(0, s.y - 1),
                          rng.uniformInt(0, s.z - 1));
    };
    int voxels = s.x * s.y * s.z;
    switch (kind) {
        case Kind::Sparse:
            for (int i = 0; i < voxels / 100; ++i)
                grid.set(randomVoxel(), MaterialId(rng.uniformInt(1, 5)));
            break;
        case Kind::Dense:
            for (int i = 0; i < voxels; ++i)
                grid.set(randomVoxel(), MaterialId(rng.uniformInt(1, 5)));
            for (int i = 0; i < voxels / 3; ++i) grid.set(randomVoxel(), kEmpty);
            break;
        case Kind::Homogeneous:
            for (int i = 0; i < 12; ++i) {
                glm::ivec3 c = glm::ivec3(rng.uniformInt(0, grid.sizeInCells().x - 1),
                                          rng.uniformInt(0, grid.sizeInCells().y - 1),
                                          rng.uniformInt(0, grid.sizeInCells().z - 1));
                grid.writeCellUniform(c, MaterialId(rng.uniformInt(1, 5)));
            }
            for (int i = 0; i < voxels / 400; ++i)
                grid.set(randomVoxel(), MaterialId(rng.uniformInt(1, 5)));
            break;
        case Kind::Mixed:
            for (int i = 0; i < 6; ++i) {
                glm::ivec3 a = randomVoxel(), b = randomVoxel();
                fillBox(grid, Box{glm::min(a, b), glm::max(a, b) + 1},
                        MaterialId(rng.uniformInt(1, 5)));
            }
            for (int i = 0; i < 4; ++i)
                fillSphere(grid, glm::vec3(randomVoxel()), rng.uniform(2.0f, 12.0f), kEmpty);
            for (int i = 0; i < voxels / 200; ++i)
                grid.set(randomVoxel(), MaterialId(rng.uniformInt(0, 5)));
            break;
    }
    grid.clearDirty();
    return grid;
}

inline glm::vec3 randomDirection(engine::Rng& rng) {
    for (;;) {
        glm::vec3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        float l = glm::length(d);
        if (l > 0.05f && l <= 1.0f) return d / l;
    }
}

// A mix of ray kinds; every tenth is axis-parallel, every tenth starts on a brick border.
inline std::vector<Ray> makeRays(const BrickGrid& grid, std::uint64_t seed, int count) {
    engine::Rng rng(seed);
    glm::vec3 s(grid.sizeInVoxels());
    std::vector<Ray> rays;
    rays.reserve(count);
    for (int i = 0; i < count; ++i) {
        Ray r;
        int kind = i % 10;
        r.origin = glm::vec3(rng.uniform(0, s.x), rng.uniform(0, s.y), rng.uniform(0, s.z));
        r.direction = randomDirection(rng);
        if (kind == 0) {  // axis-parallel, both signs, sometimes exactly on a voxel plane
            r.direction = glm::vec3(0.0f);
            r.direction[rng.uniformInt(0, 2)] = rng.nextFloat() < 0.5f ? -1.0f : 1.0f;
            if (rng.nextFloat() < 0.5f) r.origin = glm::floor(r.origin) + 0.5f;
        } else if (kind == 1) {  // starting on a brick border
            int a = rng.uniformInt(0, 2);
            r.origin[a] = 8.0f * float(rng.uniformInt(0, int(s[a] / 8.0f)));
        } else if (kind == 2) {  // from outside the world, aimed at a point inside it
            glm::vec3 target(rng.uniform(0, s.x), rng.uniform(0, s.y), rng.uniform(0, s.z));
            r.origin = target - randomDirection(rng) * (glm::length(s) * 1.2f);
            r.direction = glm::normalize(target - r.origin);
        } else if (kind == 3) {  // exactly on a voxel corner
            r.origin = glm::floor(r.origin);
        } else if (kind == 4) {  // a limited ray length
            r.tMax = rng.uniform(0.5f, 30.0f);
        }
        rays.push_back(r);
    }
    return rays;
}

// Distance from a point to the nearest integer plane on any axis: grazing hits sit near 0.
inline float distanceToCellBoundary(glm::vec3 p) {
    glm::vec3 f = glm::abs(p - glm::round(p));
    return std::min(f.x, std::min(f.y, f.z));
}

// The smallest distance to an edge between two axes (where two voxel planes meet) along the ray
// up to `t`: the place where traversals with different rounding may pick different voxels.
inline float nearestEdgeDistance(const Ray& r, float tEnd) {
    float best = 1e9f;
    glm::vec3 d = r.direction;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) continue;
        // Each crossing of an integer plane on axis a.
        float start = r.origin[a], end = r.origin[a] + d[a] * std::min(tEnd, 4096.0f);
        int lo = int(std::floor(std::min(start, end))), hi = int(std::ceil(std::max(start, end)));
        for (int k = lo; k <= hi; ++k) {
            float t = (float(k) - r.origin[a]) / d[a];
            if (t < 0.0f || t > tEnd) continue;
            glm::vec3 p = r.origin + d * t;
            for (int b = 0; b < 3; ++b) {
                if (b == a) continue;
                best = std::min(best, std::abs(p[b] - std::round(p[b])));
            }
        }
    }
    return best;
}

}  // namespace testing_worlds
