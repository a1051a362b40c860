// traceScene against one merged grid: the nearer of the static and dynamic hits is the first
// solid voxel along the ray in the union of both sets (static wins where they overlap).
#include "world/scene_trace.h"

#include <gtest/gtest.h>

#include "core/hash.h"
#include "random_worlds.h"
#include "world/ray_traversal.h"

using namespace engine::world;
using namespace testing_worlds;

namespace {

std::vector<DynamicObject> rotatedObjects() {
    std::vector<DynamicObject> objects(2);
    objects[0].modelSize = {20, 9, 13};
    BrickGrid first(objects[0].modelSize);
    for (int z = 0; z < 13; ++z)
        for (int y = 0; y < 9; ++y)
            for (int x = 0; x < 20; ++x)
                if ((x * 7 + y * 3 + z * 5) % 4 != 0)
                    first.set({x, y, z}, MaterialId(40 + (x + y) % 3));
    objects[0].model = std::make_shared<const BrickGrid>(std::move(first));
    objects[0].current = {{22.3, 17.9, 25.2}, rotationFromYawPitchRoll({31, -17, 52})};
    objects[1].modelSize = {8, 8, 8};
    BrickGrid second(objects[1].modelSize);
    for (int i = 0; i < 8; ++i) second.set({i, i, 7 - i}, 50);
    second.set({0, 0, 0}, 51);
    objects[1].model = std::make_shared<const BrickGrid>(std::move(second));
    objects[1].current = {{10.5, 30.0, 40.0}, rotationFromAxisAngle({1, 1, 0}, 73)};
    return objects;
}

}  // namespace

TEST(SceneTrace, FaceHitTIsTheEntryPlaneDistance) {
    glm::vec3 o(0.5f, 0.5f, 0.5f), d(1.0f, 0.0f, 0.0f);
    EXPECT_EQ(faceHitT(o, d, {4, 0, 0}, 0u), 3.5f);    // -X face of voxel 4: plane x = 4
    EXPECT_EQ(faceHitT(o, -d, {-3, 0, 0}, 1u), 2.5f);  // +X face of voxel -3: plane x = -2
    EXPECT_EQ(faceHitT(o, d, {0, 0, 0}, shared::FACE_INSIDE), 0.0f);
}

TEST(SceneTrace, NearerSetWinsAndStaticWinsTies) {
    BrickGrid world({32, 32, 32});
    for (int y = 0; y < 32; ++y)
        for (int z = 0; z < 32; ++z) world.set({20, y, z}, 1);  // a wall at x = 20
    std::vector<DynamicObject> objects(1);
    objects[0].modelSize = {2, 2, 2};
    BrickGrid cube({2, 2, 2});
    for (int i = 0; i < 8; ++i) cube.set({i & 1, (i >> 1) & 1, i >> 2}, 2);
    objects[0].model = std::make_shared<const BrickGrid>(std::move(cube));
    const glm::vec3 o(0.5f, 10.5f, 10.5f), d(1.0f, 0.0f, 0.0f);
    for (int x : {10, 19, 20, 25}) {
        objects[0].current = {{double(x) + 1.0, 11.0, 11.0}, {}};  // voxels x..x+1, y 10..11
        DynamicGrid dyn = voxelizeObjects(objects);
        SceneHit h = traceScene(world, &dyn, o, d, 1e30f);
        ASSERT_TRUE(h.hit);
        if (x < 20) {
            EXPECT_TRUE(h.dynamicSet) << x;
            EXPECT_EQ(h.voxel, glm::ivec3(x, 10, 10));
            EXPECT_EQ(h.material, 2u);
        } else {  // overlapping the wall (a tie) or behind it
            EXPECT_FALSE(h.dynamicSet) << x;
            EXPECT_EQ(h.voxel, glm::ivec3(20, 10, 10));
        }
        EXPECT_EQ(h.face, 0u);
        // The dynamic grid alone, in world coordinates.
        SceneHit hd = traceDynamic(dyn, o, d, 1e30f);
        EXPECT_TRUE(hd.hit && hd.dynamicSet);
        EXPECT_EQ(hd.voxel, glm::ivec3(x, 10, 10));
        EXPECT_FLOAT_EQ(faceHitT(o, d, hd.voxel, hd.face), float(x) - 0.5f);
    }
    // tMax bounds both sets.
    objects[0].current = {{11.0, 11.0, 11.0}, {}};
    DynamicGrid dyn = voxelizeObjects(objects);
    EXPECT_FALSE(traceScene(world, &dyn, o, d, 9.0f).hit);
    EXPECT_TRUE(traceScene(world, &dyn, o, d, 9.6f).hit);
    // No dynamic grid: the static traversal as is.
    SceneHit s = traceScene(world, nullptr, o, d, 1e30f);
    RayHit r = traceRay(world, Ray{o, d, 1e30f});
    EXPECT_EQ(s.voxel, r.voxel);
    EXPECT_EQ(s.t, r.t);
    EXPECT_EQ(s.steps, r.steps);
}

TEST(SceneTrace, AgreesWithTheMergedGridOnRandomRays) {
    const BrickGrid world = makeWorld(Kind::Sparse, 11, {48, 48, 56});
    std::vector<DynamicObject> objects = rotatedObjects();
    const DynamicGrid dyn = voxelizeObjects(objects);
    ASSERT_GT(dyn.grid.solidVoxels(), 500u);
    BrickGrid merged = world;
    glm::ivec3 s = dyn.grid.sizeInVoxels();
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                glm::ivec3 w = glm::ivec3(x, y, z) + dyn.origin;
                MaterialId m = dyn.grid.get({x, y, z});
                ASSERT_TRUE(m == kEmpty || world.contains(w))
                    << "objects stay inside the test world";
                if (m != kEmpty && world.get(w) == kEmpty) merged.set(w, m);
            }
    int rays = 0, dynamicHits = 0, mismatches = 0;
    for (const Ray& r : makeRays(world, 5, 20000)) {
        SceneHit h = traceScene(world, &dyn, r.origin, r.direction, r.tMax);
        RayHit m = traceRay(merged, r);
        ++rays;
        dynamicHits += h.dynamicSet;
        EXPECT_EQ(h.hit, m.hit);
        if (!h.hit || !m.hit) continue;
        if (h.voxel != m.voxel) {
            // Only where the ray grazes an edge, so the two sets' planes tie in float.
            EXPECT_LT(nearestEdgeDistance(r, m.t + 1.0f), 1e-3f);
            ++mismatches;
            continue;
        }
        EXPECT_EQ(h.material, m.material);
        EXPECT_EQ(h.dynamicSet, dyn.get(h.voxel) != kEmpty && world.get(h.voxel) == kEmpty);
    }
    EXPECT_GT(dynamicHits, rays / 50) << "the objects are actually in the way";
    EXPECT_LT(mismatches, rays / 1000);
}

// Two small objects far apart make a large dynamic grid; a ray that passes between them comes
// near no occupied box and skips the dynamic traversal (no steps), while rays that reach an
// object find the same hit as a traversal of the whole grid.
TEST(SceneTrace, RaysFarFromEveryObjectSkipTheDynamicTraversal) {
    std::vector<DynamicObject> objects = rotatedObjects();
    objects[1].current.position = {180.5, 30.0, 140.0};  // far from the first
    const DynamicGrid dyn = voxelizeObjects(objects);
    ASSERT_EQ(dyn.occupancy.size(), 2u);
    const glm::vec3 o(100.5f, 80.5f, 90.5f), d = glm::normalize(glm::vec3(0.1f, -1.0f, 0.2f));
    const Box objectsUnion{dyn.origin, dyn.origin + dyn.grid.sizeInVoxels()};
    ASSERT_TRUE(objectsUnion.contains(glm::ivec3(o + 60.0f * d)))
        << "the ray crosses the objects' union";
    SceneHit h = traceDynamic(dyn, o, d, 1e30f);
    EXPECT_FALSE(h.hit);
    EXPECT_EQ(h.steps, 0u) << "no traversal for a ray far from the objects";
    EXPECT_FALSE(nearsOccupancy(dyn, o, d, 1e30f));
    // Rays from everywhere at the objects: the same hits as the whole grid's traversal.
    engine::Rng rng(9);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 lo(dyn.origin), hi(dyn.origin + dyn.grid.sizeInVoxels());
        const glm::vec3 target(rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y),
                               rng.uniform(lo.z, hi.z));
        const glm::vec3 from(rng.uniform(lo.x - 20, hi.x + 20), rng.uniform(lo.y - 20, hi.y + 20),
                             rng.uniform(lo.z - 20, hi.z + 20));
        if (glm::length(target - from) < 1e-3f) continue;
        const glm::vec3 dir = glm::normalize(target - from);
        const float tMax = i % 5 == 0 ? rng.uniform(1.0f, 80.0f) : 1e30f;
        SceneHit skipped = traceDynamic(dyn, from, dir, tMax);
        RayHit whole = traceRay(dyn.grid, Ray{from - glm::vec3(dyn.origin), dir, tMax});
        ASSERT_EQ(skipped.hit, whole.hit) << "ray " << i;
        if (!whole.hit) continue;
        ++hits;
        EXPECT_EQ(skipped.voxel, whole.voxel + dyn.origin) << "ray " << i;
        EXPECT_EQ(skipped.t, whole.t) << "ray " << i;
        EXPECT_EQ(skipped.steps, whole.steps) << "ray " << i;
    }
    EXPECT_GT(hits, 100);
}
