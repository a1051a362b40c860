// Re-voxelisation of dynamic objects into the world-aligned dynamic grid.
#include "world/dynamic_grid.h"

#include <algorithm>
#include <gtest/gtest.h>

#include "shared/dynamic_grid.h"

using namespace engine::world;

namespace {

// An asymmetric 6x4x2 model: every voxel a different material, so any flip or swap shows.
DynamicObject asymmetricObject() {
    DynamicObject o;
    o.modelSize = {6, 4, 2};
    BrickGrid model(o.modelSize);
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 6; ++x) model.set({x, y, z}, MaterialId(1 + x + 6 * y + 24 * z));
    model.set({5, 3, 1}, kEmpty);  // and a hole
    o.model = std::make_shared<const BrickGrid>(std::move(model));
    return o;
}

std::size_t countSolid(const DynamicGrid& g) {
    std::size_t n = 0;
    glm::ivec3 s = g.grid.sizeInVoxels();
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) n += g.grid.get({x, y, z}) != kEmpty;
    return n;
}

}  // namespace

TEST(DynamicGrid, EmptyWithoutObjects) {
    DynamicGrid g = voxelizeObjects({});
    EXPECT_FALSE(g.present());
    EXPECT_EQ(g.get({0, 0, 0}), kEmpty);
}

TEST(DynamicGrid, WholeVoxelTranslationIsExact) {
    DynamicObject o = asymmetricObject();
    // The pivot is (3, 2, 1): a centre at (103, -18, 41) puts model voxel (0,0,0) at (100, -20,
    // 40).
    o.current = {{103, -18, 41}, {}};
    DynamicGrid g = voxelizeObjects(std::span(&o, 1));
    ASSERT_TRUE(g.present());
    EXPECT_EQ(g.origin % 8, glm::ivec3(0)) << "brick-aligned";
    for (int z = -1; z < 3; ++z)
        for (int y = -1; y < 5; ++y)
            for (int x = -1; x < 7; ++x)
                EXPECT_EQ(g.get(glm::ivec3(100, -20, 40) + glm::ivec3(x, y, z)),
                          o.model->get({x, y, z}))
                    << x << y << z;
    EXPECT_EQ(countSolid(g), o.model->solidVoxels());
    ASSERT_EQ(g.instances.size(), 1u);
    EXPECT_EQ(g.instances[0].bounds.min, glm::ivec3(100, -20, 40));
    EXPECT_EQ(g.instances[0].bounds.max, glm::ivec3(106, -16, 42));
}

TEST(DynamicGrid, QuarterTurnGivesExactlyTheRotatedVoxels) {
    DynamicObject o = asymmetricObject();
    const glm::dvec3 centre(50, 20, 30);
    for (glm::dvec3 ypr : {glm::dvec3(90, 0, 0), glm::dvec3(0, 90, 0), glm::dvec3(0, 0, -90),
                           glm::dvec3(180, 90, 0)}) {
        o.current = {centre, rotationFromYawPitchRoll(ypr)};
        DynamicGrid g = voxelizeObjects(std::span(&o, 1));
        // Exact integer rotation of each model voxel centre about the pivot.
        const glm::dmat3 r = glm::mat3_cast(o.current.rotation);
        glm::imat3x3 ri;
        for (int c = 0; c < 3; ++c)
            for (int row = 0; row < 3; ++row) ri[c][row] = int(std::lround(r[c][row]));
        std::size_t expected = 0;
        for (int z = 0; z < 2; ++z)
            for (int y = 0; y < 4; ++y)
                for (int x = 0; x < 6; ++x) {
                    // centre-relative doubled coordinates stay integral: 2(v + 0.5) - 2 pivot.
                    glm::ivec3 rel2 =
                        glm::ivec3(2 * x + 1, 2 * y + 1, 2 * z + 1) - glm::ivec3(6, 4, 2);
                    glm::ivec3 w2 = ri * rel2 + glm::ivec3(2.0 * centre);
                    glm::ivec3 world = (w2 - 1) / 2;
                    EXPECT_EQ(g.get(world), o.model->get({x, y, z}))
                        << "ypr " << ypr.x << "," << ypr.y << "," << ypr.z;
                    expected += o.model->get({x, y, z}) != kEmpty;
                }
        EXPECT_EQ(countSolid(g), expected) << "nothing else was written";
    }
}

TEST(DynamicGrid, ArbitraryRotationKeepsTheVolume) {
    DynamicObject o;
    o.modelSize = {24, 16, 16};
    BrickGrid model(o.modelSize);
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 24; ++x) model.set({x, y, z}, 3);
    o.model = std::make_shared<const BrickGrid>(std::move(model));
    o.current = {{40.3, 41.7, 39.1}, rotationFromYawPitchRoll({33, 21, 12})};
    DynamicGrid g = voxelizeObjects(std::span(&o, 1));
    double n = double(countSolid(g));
    EXPECT_NEAR(n / (24.0 * 16 * 16), 1.0, 0.05);
    // Every written voxel's centre maps back inside the model.
    glm::dmat4 inv = glm::inverse(o.worldFromModel(o.current));
    glm::ivec3 s = g.grid.sizeInVoxels();
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                glm::dvec3 m(inv *
                             glm::dvec4(glm::dvec3(glm::ivec3(x, y, z) + g.origin) + 0.5, 1.0));
                bool inside = glm::all(glm::greaterThanEqual(m, glm::dvec3(0))) &&
                              glm::all(glm::lessThan(m, glm::dvec3(o.modelSize)));
                EXPECT_EQ(g.grid.get({x, y, z}) != kEmpty, inside);
            }
}

TEST(DynamicGrid, UpdateRebuildsOnlyWhenPosesChange) {
    std::vector<DynamicObject> objects{asymmetricObject()};
    objects[0].path = ObjectPath({{0.0, {10, 10, 10}, {}}, {2.0, {30, 10, 10}, {}}}, false);
    DynamicGrid g;
    EXPECT_TRUE(updateDynamicObjects(objects, g, 0.0, 0.0));
    std::uint64_t r = g.revision;
    EXPECT_FALSE(updateDynamicObjects(objects, g, 0.0, 0.0));
    EXPECT_EQ(g.revision, r);
    EXPECT_TRUE(updateDynamicObjects(objects, g, 1.0, 0.0));
    EXPECT_GT(g.revision, r);
    EXPECT_EQ(objects[0].previous.position, glm::dvec3(10, 10, 10));
    EXPECT_EQ(objects[0].current.position, glm::dvec3(20, 10, 10));
    // prevFromCurrent takes this frame's point back to last frame's.
    glm::dvec3 p(g.instances[0].prevFromCurrent() * glm::dvec4(21.5, 10.5, 10.5, 1.0));
    EXPECT_NEAR(glm::length(p - glm::dvec3(11.5, 10.5, 10.5)), 0.0, 1e-9);
}

TEST(DynamicGrid, FirstObjectWinsWhereObjectsOverlap) {
    std::vector<DynamicObject> objects{asymmetricObject(), asymmetricObject()};
    objects[0].current = {{3, 2, 1}, {}};
    objects[1].current = {{5, 2, 1}, {}};
    DynamicGrid g = voxelizeObjects(objects);
    EXPECT_EQ(g.get({2, 0, 0}), objects[0].model->get({2, 0, 0}));
    EXPECT_EQ(g.get({7, 0, 0}), objects[1].model->get({5, 0, 0}));
}

// The coarse occupancy holds every voxel of the grid in at most DYNAMIC_OCCUPANCY_BOXES boxes of
// whole cells, and stays near the objects: six small objects spread over a large union, more
// objects than boxes, so some boxes hold two.
TEST(DynamicGrid, OccupancyBoxesHoldEveryVoxelInFewCells) {
    std::vector<DynamicObject> objects(6, asymmetricObject());
    for (std::size_t i = 0; i < objects.size(); ++i)
        objects[i].current = {{7.0 + 50.0 * double(i), 3.0 + 9.0 * double(i % 2), -30.0}, {}};
    DynamicGrid g = voxelizeObjects(objects);
    ASSERT_TRUE(g.present());
    ASSERT_EQ(g.occupancy.size(), std::size_t(shared::DYNAMIC_OCCUPANCY_BOXES));
    for (std::size_t i = 0; i < g.occupancy.size(); ++i) {
        const Box& b = g.occupancy[i];
        EXPECT_EQ(b.min % 8, glm::ivec3(0));
        EXPECT_EQ(b.max % 8, glm::ivec3(0));
        EXPECT_FALSE(b.empty());
        // Objects 2 and 3 have a box each (0 and 1 share theirs with 4 and 5): the cells of one
        // 6x4x2 object, at most 2 per axis.
        if (i >= 2) {
            EXPECT_TRUE(glm::all(glm::lessThanEqual(b.size(), glm::ivec3(16)))) << i;
        }
    }
    const glm::ivec3 s = g.grid.sizeInVoxels();
    std::size_t solid = 0;
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                const glm::ivec3 w = glm::ivec3(x, y, z) + g.origin;
                if (g.get(w) == kEmpty) continue;
                ++solid;
                EXPECT_TRUE(std::any_of(g.occupancy.begin(), g.occupancy.end(),
                                        [&](const Box& b) { return b.contains(w); }))
                    << w.x << "," << w.y << "," << w.z;
            }
    EXPECT_EQ(solid, 6 * objects[0].model->solidVoxels());
}
