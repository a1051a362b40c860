#include <cmath>
#include <gtest/gtest.h>

#include "random_worlds.h"

using namespace engine::world;
using namespace testing_worlds;

namespace {

// The obviously-right reference: Amanatides-Woo through every voxel, reading grid.get().
RayHit naiveTrace(const BrickGrid& grid, const Ray& ray) {
    glm::vec3 o = ray.origin, d = ray.direction;
    glm::vec3 size(grid.sizeInVoxels());
    float tEnter = 0.0f, tExit = ray.tMax;
    int enterAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) {
            if (o[a] < 0.0f || o[a] >= size[a]) return {};
            continue;
        }
        float t0 = (0.0f - o[a]) / d[a], t1 = (size[a] - o[a]) / d[a];
        if (std::min(t0, t1) > tEnter) {
            tEnter = std::min(t0, t1);
            enterAxis = a;
        }
        tExit = std::min(tExit, std::max(t0, t1));
    }
    if (tEnter > tExit) return {};
    glm::vec3 p = o + d * tEnter;
    glm::ivec3 v = glm::clamp(glm::ivec3(glm::floor(p)), glm::ivec3(0), grid.sizeInVoxels() - 1);
    std::uint32_t face = shared::FACE_INSIDE;
    if (enterAxis >= 0) {
        v[enterAxis] = d[enterAxis] > 0 ? 0 : grid.sizeInVoxels()[enterAxis] - 1;
        face = std::uint32_t(enterAxis * 2 + (d[enterAxis] > 0 ? 0 : 1));
    }
    glm::ivec3 step(0);
    glm::vec3 tMax(INFINITY), tDelta(INFINITY);
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) continue;
        step[a] = d[a] > 0 ? 1 : -1;
        tDelta[a] = std::abs(1.0f / d[a]);
        float boundary = float(v[a] + (d[a] > 0 ? 1 : 0));
        tMax[a] = (boundary - o[a]) / d[a];
    }
    float t = tEnter;
    while (grid.contains(v)) {
        if (grid.get(v) != kEmpty) return RayHit{true, v, face, t, grid.get(v), 0};
        int a = 0;  // ties go to the lowest axis, as in traceRay
        if (tMax.y < tMax[a]) a = 1;
        if (tMax.z < tMax[a]) a = 2;
        t = tMax[a];
        if (t > ray.tMax) return {};
        v[a] += step[a];
        tMax[a] += tDelta[a];
        face = std::uint32_t(a * 2 + (step[a] > 0 ? 0 : 1));
    }
    return {};
}

// Rays that start exactly on a voxel edge or corner (a tenth of the test rays, by design) may step
// out through either neighbour at t = 0; walks with different block sizes can pick differently.
// Such grazing rays are allowed to disagree, at this rate at most.
constexpr int kAllowedMismatchesPer10000 = 5;

bool sameHit(const RayHit& a, const RayHit& b) {
    return a.hit == b.hit &&
           (!a.hit || (a.voxel == b.voxel && a.face == b.face && a.material == b.material));
}

}  // namespace

TEST(RayTraversal, AgreesWithNaiveVoxelWalkOnRandomWorlds) {
    int total = 0, mismatches = 0, hits = 0;
    for (Kind kind : {Kind::Sparse, Kind::Dense, Kind::Homogeneous, Kind::Mixed}) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            BrickGrid grid = makeWorld(kind, seed);
            for (const Ray& ray : makeRays(grid, seed * 31 + 7, 4000)) {
                RayHit fast = traceRay(grid, ray);
                RayHit naive = naiveTrace(grid, ray);
                ++total;
                hits += fast.hit;
                if (sameHit(fast, naive)) {
                    if (fast.hit) {
                        EXPECT_NEAR(fast.t, naive.t, 1e-3f * std::max(1.0f, naive.t));
                    }
                    continue;
                }
                ++mismatches;
                // A disagreement is only allowed where the ray grazes an edge between voxels.
                float tEnd = std::max(fast.hit ? fast.t : 0.0f, naive.hit ? naive.t : 0.0f) + 1.0f;
                EXPECT_LT(nearestEdgeDistance(ray, tEnd), 1e-4f)
                    << kindName(kind) << " seed " << seed;
            }
        }
    }
    std::printf("CPU hierarchical vs naive walk: %d of %d rays differ (%d hits)\n", mismatches,
                total, hits);
    EXPECT_GT(hits, total / 4);
    EXPECT_LE(mismatches * 10000, total * kAllowedMismatchesPer10000);
}

TEST(RayTraversal, HierarchicalTakesFewerStepsThanPlainWithSameHits) {
    std::uint64_t stepsH = 0, stepsP = 0;
    int total = 0, mismatches = 0;
    for (Kind kind : {Kind::Sparse, Kind::Mixed, Kind::Homogeneous}) {
        BrickGrid grid = makeWorld(kind, 5);
        for (const Ray& ray : makeRays(grid, 99, 5000)) {
            RayHit h = traceRay(grid, ray, TraversalMode::Hierarchical);
            RayHit p = traceRay(grid, ray, TraversalMode::PlainTwoLevel);
            stepsH += h.steps;
            stepsP += p.steps;
            ++total;
            if (sameHit(h, p)) continue;
            ++mismatches;
            float tEnd = std::max(h.hit ? h.t : 0.0f, p.hit ? p.t : 0.0f) + 1.0f;
            EXPECT_LT(nearestEdgeDistance(ray, tEnd), 1e-4f);
        }
    }
    std::printf("steps per ray: hierarchical %.2f, plain %.2f\n", double(stepsH) / total,
                double(stepsP) / total);
    EXPECT_LT(stepsH, stepsP);
    EXPECT_LE(mismatches * 10000, total * kAllowedMismatchesPer10000);
}

TEST(RayTraversal, RayStartingInsideSolidHitsAtZero) {
    BrickGrid grid({16, 16, 16});
    fillBox(grid, Box{{0, 0, 0}, {16, 8, 16}}, 2);
    RayHit h = traceRay(grid, Ray{{3.5f, 2.5f, 3.5f}, {0.0f, 1.0f, 0.0f}});
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.face, shared::FACE_INSIDE);
    EXPECT_EQ(h.t, 0.0f);
    EXPECT_EQ(h.voxel, glm::ivec3(3, 2, 3));
}

TEST(RayTraversal, FaceAndDistanceOfASimpleHit) {
    BrickGrid grid({32, 32, 32});
    grid.set({20, 5, 5}, 4);
    RayHit h = traceRay(grid, Ray{{0.5f, 5.5f, 5.5f}, {1.0f, 0.0f, 0.0f}});
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.voxel, glm::ivec3(20, 5, 5));
    EXPECT_EQ(h.face, 0u);  // entered through its -X face
    EXPECT_FLOAT_EQ(h.t, 19.5f);
    EXPECT_EQ(h.material, 4);
    // From outside the world, through the +Y side, downwards.
    RayHit down = traceRay(grid, Ray{{20.5f, 100.0f, 5.5f}, {0.0f, -1.0f, 0.0f}});
    ASSERT_TRUE(down.hit);
    EXPECT_EQ(down.face, shared::FACE_POS_Y);
    EXPECT_FLOAT_EQ(down.t, 94.0f);
    // tMax stops short of it.
    EXPECT_FALSE(traceRay(grid, Ray{{0.5f, 5.5f, 5.5f}, {1.0f, 0.0f, 0.0f}, 19.0f}).hit);
    // A ray leaving the world misses.
    EXPECT_FALSE(traceRay(grid, Ray{{0.5f, 5.5f, 5.5f}, {-1.0f, 0.0f, 0.0f}}).hit);
}

// A world whose size is not a multiple of 32 voxels: its last super cells overhang the world's
// edge, and a ray leaving through the overhang must miss, not wrap into the next row of cells.
TEST(RayTraversal, RaysLeavingThroughAnOverhangingSuperCellMiss) {
    BrickGrid grid({40, 80, 40});  // 5 x 10 x 5 cells; super cells reach y = 96
    fillBox(grid, Box{{0, 0, 0}, {40, 12, 40}}, 1);
    // One voxel low in the top row of super cells: rays cross empty super cells (32 voxels at a
    // step), rise out of the world inside them, then enter the one that is not empty.
    grid.set({36, 65, 10}, 2);
    engine::Rng rng(17);
    int misses = 0;
    for (int i = 0; i < 2000; ++i) {
        Ray r{{rng.uniform(1, 31), rng.uniform(70, 79.5f), rng.uniform(1, 31)}, {}};
        r.direction = glm::normalize(
            glm::vec3(rng.uniform(0.3f, 1), rng.uniform(0.02f, 0.4f), rng.uniform(-0.3f, 0.3f)));
        RayHit h = traceRay(grid, r);
        ASSERT_FALSE(h.hit) << "ray " << i << " hit voxel " << h.voxel.x << "," << h.voxel.y << ","
                            << h.voxel.z;
        misses += !h.hit;
    }
    EXPECT_EQ(misses, 2000);
}
