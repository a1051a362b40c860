// The walking player's physics (world/player_body.h, world/player_collision.h) against the CPU
// grid: never inside a solid voxel, no tunnelling at any speed, one-voxel steps climbed and
// two-voxel ones not, carried by a moving platform, crouching, replayed exactly.
#include "world/player_body.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <optional>
#include <tuple>

#include "core/hash.h"
#include "random_worlds.h"
#include "world/dynamic_grid.h"
#include "world/world_edits.h"

using namespace engine::world;

namespace {

constexpr MaterialId kStone = 1;

// An independent check, voxel by voxel through BrickGrid::get and DynamicGrid::get: the first
// solid voxel the box's interior overlaps, if any.
std::optional<glm::ivec3> solidInside(const BrickGrid& grid, const DynamicGrid* dyn,
                                      const PlayerBox& b) {
    for (int z = int(std::floor(b.min.z)); z < b.max.z; ++z)
        for (int y = int(std::floor(b.min.y)); y < b.max.y; ++y)
            for (int x = int(std::floor(b.min.x)); x < b.max.x; ++x) {
                // Voxel [v, v+1) overlaps the open box when v < max and v + 1 > min.
                if (!(x + 1 > b.min.x && y + 1 > b.min.y && z + 1 > b.min.z)) continue;
                glm::ivec3 v(x, y, z);
                if (grid.get(v) != kEmpty || (dyn && dyn->get(v) != kEmpty)) return v;
            }
    return std::nullopt;
}

// 64 x 32 x 64 with a stone floor whose top is at y = 4.
BrickGrid flatWorld() {
    BrickGrid grid({64, 32, 64});
    fillBox(grid, Box{{0, 0, 0}, {64, 4, 64}}, kStone);
    return grid;
}

PlayerIntent walk(glm::dvec2 direction) {
    PlayerIntent i;
    i.move = direction;
    return i;
}

// Runs `seconds` of 1/30 s frames.
void run(PlayerBody& body, const CollisionWorld& world, const PlayerIntent& intent,
         double seconds) {
    for (int f = 0; f < int(std::lround(seconds * 30.0)); ++f)
        body.advance(world, intent, 1.0 / 30.0);
}

}  // namespace

TEST(PlayerCollision, SweepStopsAtTheFirstSolidLayerWhateverTheDistance) {
    BrickGrid grid = flatWorld();
    fillBox(grid, Box{{40, 4, 0}, {41, 8, 64}}, kStone);  // a wall one voxel thick at x = 40
    CollisionWorld world{grid};
    for (double distance : {0.3, 0.5, 1.0, 17.0, 1e3, 1e6}) {
        PlayerBox b{{10.0, 4.0 + kSkin, 10.0}, {10.6, 5.8, 10.6}};
        double moved = sweepAxis(world, b, 0, distance);
        EXPECT_LE(moved, distance);
        EXPECT_LE(b.max.x, 40.0) << "through the wall at distance " << distance;
        if (distance > 40.0) {
            EXPECT_NEAR(b.max.x, 40.0, 2 * kSkin);
        }
        EXPECT_FALSE(solidInside(grid, nullptr, b));
        // And back the other way from beyond it.
        PlayerBox c{{50.0, 4.0 + kSkin, 10.0}, {50.6, 5.8, 10.6}};
        sweepAxis(world, c, 0, -distance);
        EXPECT_GE(c.min.x, 41.0) << "through the wall backwards at distance " << distance;
    }
}

TEST(PlayerCollision, WorldSidesAndFloorAreSolidTheSkyIsNot) {
    BrickGrid grid({16, 16, 16});
    CollisionWorld world{grid};
    PlayerBox b{{1.0, 1.0, 1.0}, {1.6, 2.8, 1.6}};
    sweepAxis(world, b, 0, -100.0);
    EXPECT_GE(b.min.x, 0.0);
    sweepAxis(world, b, 1, -100.0);
    EXPECT_GE(b.min.y, 0.0);
    EXPECT_EQ(sweepAxis(world, b, 1, 100.0), 100.0);
}

TEST(PlayerBody, CannotPassAOneVoxelWallAtTheHighestSpeed) {
    BrickGrid grid = flatWorld();
    fillBox(grid, Box{{40, 4, 0}, {41, 8, 64}}, kStone);   // a wall at x = 40
    fillBox(grid, Box{{0, 20, 0}, {30, 21, 64}}, kStone);  // a one-voxel slab over x < 30
    CollisionWorld world{grid};
    // Running at the body's highest speed (its terminal fall speed), and far beyond it.
    for (double speed : {PlayerSettings{}.maxSpeed(), 1e4}) {
        PlayerSettings s;
        s.runSpeed = speed;
        PlayerBody body(s);
        body.place(world, {20.0, 4.0, 10.0});
        PlayerIntent intent = walk({1.0, 0.0});
        intent.run = true;
        for (int f = 0; f < 60; ++f) {
            body.advance(world, intent, 1.0 / 30.0);
            ASSERT_LE(body.box().max.x, 40.0) << "speed " << speed << " frame " << f;
            ASSERT_FALSE(solidInside(grid, nullptr, body.box()));
        }
        EXPECT_NEAR(body.box().max.x, 40.0, 1e-3);
    }
    // Falling from the sky at terminal speed onto the slab.
    PlayerBody body;
    body.place(world, {10.0, 200.0, 10.0});
    double fastest = 0.0;
    for (int f = 0; f < 300; ++f) {
        body.advance(world, {}, 1.0 / 30.0);
        fastest = std::max(fastest, -body.velocity().y);
        ASSERT_GE(body.feet().y, 21.0) << "through the slab at frame " << f;
    }
    EXPECT_DOUBLE_EQ(fastest, PlayerSettings{}.maxFallSpeed) << "it did reach terminal speed";
    EXPECT_TRUE(body.onGround());
    EXPECT_NEAR(body.feet().y, 21.0, 1e-3);
}

TEST(PlayerBody, NeverInsideASolidVoxelOnRandomWalksThroughRandomWorlds) {
    using testing_worlds::Kind;
    for (Kind kind : {Kind::Sparse, Kind::Homogeneous, Kind::Mixed}) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            BrickGrid grid = testing_worlds::makeWorld(kind, seed, {48, 40, 48});
            CollisionWorld world{grid};
            PlayerBody body;
            engine::Rng rng(seed * 977 + std::uint64_t(kind));
            body.place(world, {24.0, 20.0, 24.0});
            ASSERT_FALSE(solidInside(grid, nullptr, body.box()));
            PlayerIntent intent;
            double travelled = 0.0;
            for (int t = 0; t < 3000; ++t) {
                const glm::dvec3 before = body.feet();
                if (t % 30 == 0) {  // a new whim every quarter second
                    double a = rng.uniform(0.0f, 6.2831853f);
                    intent.move =
                        glm::dvec2(std::cos(a), std::sin(a)) * double(rng.uniform(0.0f, 1.0f));
                    intent.run = rng.uniform(0.0f, 1.0f) < 0.5f;
                    intent.jump = rng.uniform(0.0f, 1.0f) < 0.3f;
                    intent.crouch = rng.uniform(0.0f, 1.0f) < 0.2f;
                }
                body.tick(world, intent);
                auto inside = solidInside(grid, nullptr, body.box());
                ASSERT_FALSE(inside)
                    << testing_worlds::kindName(kind) << " seed " << seed << " tick " << t
                    << ": voxel " << inside->x << " " << inside->y << " " << inside->z;
                travelled += glm::length(body.feet() - before);
            }
            EXPECT_GT(travelled, 40.0)
                << "the walk went somewhere: " << testing_worlds::kindName(kind) << " seed "
                << seed;
        }
    }
}

TEST(PlayerBody, ClimbsAOneVoxelStepButNotATwoVoxelOne) {
    BrickGrid grid = flatWorld();
    fillBox(grid, Box{{20, 4, 0}, {64, 5, 64}},
            kStone);  // from x = 20 the ground is one voxel higher
    fillBox(grid, Box{{40, 5, 0}, {64, 7, 64}}, kStone);  // from x = 40 two more
    CollisionWorld world{grid};
    PlayerBody body;
    body.place(world, {10.0, 4.0, 32.0});
    run(body, world, walk({1.0, 0.0}), 10.0);
    EXPECT_NEAR(body.feet().y, 5.0, 1e-3) << "on the one-voxel step";
    EXPECT_NEAR(body.box().max.x, 40.0, 1e-3) << "stopped at the two-voxel step";
    EXPECT_TRUE(body.onGround());
    // A jump does not help either: step-up needs the ground under the feet, and a jump reaches
    // 1.25 voxels, not 2.
    PlayerIntent jumpAhead = walk({1.0, 0.0});
    jumpAhead.jump = true;
    run(body, world, jumpAhead, 3.0);
    EXPECT_LE(body.box().max.x, 40.0);
}

TEST(PlayerBody, StepHeightScalesWithThePlayer) {
    // Scale 2: a 1.2 x 3.6 x 1.2 body steps up 2 voxels; scale 0.5 steps up half a voxel, so not
    // onto a whole one.
    for (auto [scale, step, climbs] : {std::tuple{2.0, 2, true}, std::tuple{0.5, 1, false}}) {
        BrickGrid grid = flatWorld();
        fillBox(grid, Box{{20, 4, 0}, {64, 4 + step, 64}}, kStone);
        CollisionWorld world{grid};
        PlayerSettings s;
        s.scale = scale;
        PlayerBody body(s);
        body.place(world, {10.0, 4.0, 32.0});
        run(body, world, walk({1.0, 0.0}), 8.0);
        EXPECT_NEAR(body.feet().y, climbs ? 4.0 + step : 4.0, 1e-3) << "scale " << scale;
        EXPECT_EQ(body.feet().x > 20.0, climbs) << "scale " << scale;
    }
}

TEST(PlayerBody, JumpsAsHighAsSet) {
    BrickGrid grid = flatWorld();
    CollisionWorld world{grid};
    PlayerBody body;
    body.place(world, {32.0, 4.0, 32.0});
    run(body, world, {}, 0.5);
    ASSERT_TRUE(body.onGround());
    PlayerIntent jump;
    jump.jump = true;
    double highest = 0.0;
    body.tick(world, jump);
    for (int t = 0; t < 120; ++t) {
        body.tick(world, {});
        highest = std::max(highest, body.feet().y - 4.0);
    }
    EXPECT_NEAR(highest, PlayerSettings{}.jumpHeight, 0.1);
    EXPECT_TRUE(body.onGround());
}

TEST(PlayerBody, CrouchLowersTheBoxAndStaysDownUnderALowCeiling) {
    // At scale 1.25 the body is 2.25 voxels tall standing and 1.875 crouched; from x = 30 a
    // ceiling leaves a gap of 2 voxels over the floor (top at y = 4, ceiling from y = 6).
    BrickGrid grid = flatWorld();
    fillBox(grid, Box{{30, 6, 0}, {64, 7, 64}}, kStone);
    PlayerSettings s;
    s.scale = 1.25;
    CollisionWorld world{grid};
    PlayerBody body(s);
    body.place(world, {20.0, 4.0, 32.0});
    run(body, world, {}, 0.5);
    const double standing = body.box().max.y - body.box().min.y;
    EXPECT_NEAR(standing, 1.8 * 1.25, 1e-9);
    // Standing, the body does not fit under the ceiling.
    run(body, world, walk({1.0, 0.0}), 3.0);
    EXPECT_LE(body.box().max.x, 30.0 + 1e-9) << "a standing body walked under a 2-voxel ceiling";
    // Crouched it does; the box and the eye are lower.
    PlayerIntent crouchWalk = walk({1.0, 0.0});
    crouchWalk.crouch = true;
    run(body, world, crouchWalk, 0.1);
    EXPECT_TRUE(body.crouching());
    EXPECT_NEAR(body.box().max.y - body.box().min.y, 1.5 * 1.25, 1e-9);
    EXPECT_NEAR(body.eye().y - body.feet().y, 1.32 * 1.25, 1e-9);
    run(body, world, crouchWalk, 3.0);
    EXPECT_GT(body.box().min.x, 31.0) << "the crouched body went under the ceiling";
    // Letting go of crouch under the ceiling keeps it down; out in the open it stands.
    run(body, world, {}, 0.5);
    EXPECT_TRUE(body.crouching()) << "stood up into the ceiling";
    EXPECT_FALSE(solidInside(grid, nullptr, body.box()));
    run(body, world, walk({-1.0, 0.0}), 4.0);
    EXPECT_FALSE(body.crouching());
}

TEST(PlayerBody, LandsOnAMovingPlatformAndMovesWithIt) {
    BrickGrid grid = flatWorld();
    CollisionWorld world{grid};
    // A 10 x 2 x 10 platform sliding along +x from x = 15 to x = 45 (centre) over 3 s, its top at
    // y = 10, then standing still.
    DynamicObject platform;
    platform.name = "platform";
    platform.modelSize = {10, 2, 10};
    BrickGrid model(platform.modelSize);
    fillBox(model, Box{{0, 0, 0}, {10, 2, 10}}, kStone);
    platform.model = std::make_shared<const BrickGrid>(std::move(model));
    ObjectKey a, b, c;
    a.time = 0.0, a.position = {15.0, 9.0, 32.0};
    b.time = 3.0, b.position = {45.0, 9.0, 32.0};
    c.time = 10.0, c.position = {45.0, 9.0, 32.0};
    platform.path = ObjectPath({a, b, c}, false);
    std::vector<DynamicObject> objects{platform};
    DynamicGrid dyn;
    world.dynamic = &dyn;

    PlayerBody body;
    const double dt = 1.0 / 30.0;
    updateDynamicObjects(objects, dyn, 0.0, 0.0);
    body.place(world, {17.0, 12.0, 32.0});  // two voxels over the platform, falling as it slides
    double landedAt = -1.0, xAtLanding = 0.0;
    for (int f = 1; f <= 90; ++f) {
        const double t = f * dt;
        updateDynamicObjects(objects, dyn, t, t - dt);
        body.advance(world, {}, dt);
        ASSERT_FALSE(solidInside(grid, &dyn, body.box())) << "frame " << f;
        if (landedAt < 0.0 && body.supportObject()) {
            landedAt = t;
            xAtLanding = body.feet().x;
            EXPECT_NEAR(body.feet().y, 10.0, 1e-3) << "on the platform's top";
        }
    }
    ASSERT_GE(landedAt, 0.0) << "never landed on the platform";
    EXPECT_LT(landedAt, 1.0);
    EXPECT_EQ(*body.supportObject(), 0u);
    // The platform's centre went from its position at landing to 45; the feet went as far.
    const double platformMoved = 45.0 - objects[0].poseAt(landedAt).position.x;
    EXPECT_GT(platformMoved, 20.0);
    EXPECT_NEAR(body.feet().x - xAtLanding, platformMoved, 1.0);
    EXPECT_NEAR(body.feet().y, 10.0, 1e-3);
    EXPECT_NEAR(body.feet().z, 32.0, 1e-9) << "carried only along the platform's motion";
}

TEST(PlayerBody, IsLiftedOutOfVoxelsThatAppearInside) {
    BrickGrid grid = flatWorld();
    CollisionWorld world{grid};
    PlayerBody body;
    body.place(world, {10.5, 4.0, 10.5});
    run(body, world, {}, 0.2);
    fillBox(grid, Box{{9, 4, 9}, {12, 6, 12}}, kStone);  // an undo fills the place it stands in
    PlayerFrameReport r = body.advance(world, {}, 1.0 / 30.0);
    EXPECT_NEAR(r.liftedBy, 2.0, 1e-3);
    EXPECT_FALSE(solidInside(grid, nullptr, body.box()));
}

TEST(PlayerBody, ReplaysExactly) {
    BrickGrid grid = testing_worlds::makeWorld(testing_worlds::Kind::Mixed, 5, {48, 40, 48});
    CollisionWorld world{grid};
    PlayerBody first, second;
    first.place(world, {24.0, 30.0, 24.0});
    second.place(world, {24.0, 30.0, 24.0});
    for (int f = 0; f < 300; ++f) {
        PlayerIntent i = walk({std::cos(f * 0.05), std::sin(f * 0.03)});
        i.jump = f % 40 < 5;
        // Frame times that are not whole ticks: the accumulator carries the remainder.
        const double dt = 1.0 / 30.0 + (f % 7) * 1e-3;
        first.advance(world, i, dt);
        second.advance(world, i, dt);
        ASSERT_EQ(first.feet(), second.feet()) << "frame " << f;
    }
}

TEST(PlayerBody, NeverSpinsWhereverItStarts) {
    // Walk mode puts the body at the camera: anywhere a scene or .vdb file may put one (within
    // kCoordinateRange) and, for safety, anywhere at all. Its work per frame, counted in voxel
    // reads, stays bounded by the world, not by the distance to it: the lift out of solid voxels
    // tries each level up to 4096 above the top with a box of 2 x 3 x 2 voxels, and the ticks
    // read a few layers each.
    const BrickGrid grid = flatWorld();
    const std::uint64_t bound = (32 + 4096 + 2) * 12 + 12 * 8 * 3 * 12;
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const glm::dvec3 starts[] = {
        {32, 1e7, 32},    {32, -1e7, 32}, {1e7, 10, 1e7},      {-1e7, 10, -1e7}, {32, 2.5e9, 32},
        {32, -2.5e9, 32}, {32, 1e30, 32}, {1e30, -1e30, 1e30}, {32, inf, 32},    {32, -inf, 32},
        {inf, inf, -inf}, {32, nan, 32},  {nan, nan, nan},     {32, 4.0, 32}};
    for (const glm::dvec3& start : starts) {
        SCOPED_TRACE(testing::Message()
                     << "starting at " << start.x << ", " << start.y << ", " << start.z);
        PlayerBody body;
        CollisionWorld world{grid};
        body.place(world, start);
        ASSERT_LE(world.voxelReads, bound) << "placing it";
        PlayerIntent intent = walk({0.6, 0.8});
        intent.jump = true;
        for (int f = 0; f < 20; ++f) {
            world.voxelReads = 0;
            body.advance(world, intent, 1.0 / 30.0);
            ASSERT_LE(world.voxelReads, bound) << "frame " << f;
        }
        // Wherever it started, it is somewhere real now: inside the world's sides, above its floor.
        const glm::dvec3 feet = body.feet();
        EXPECT_TRUE(std::isfinite(feet.x) && std::isfinite(feet.y) && std::isfinite(feet.z));
        EXPECT_FALSE(solidInside(grid, nullptr, body.box()));
        EXPECT_GE(feet.y, 4.0);
    }
}
