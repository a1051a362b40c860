// Dynamic objects on the GPU: traceScene against the CPU reference hit for hit, the G-buffer's
// dynamic flag and world voxels, motion vectors that follow a moving object, and shadows cast by
// objects.
#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "gpu/texel_buffer_limit.h"
#include "scene/scene_file.h"
#include "world/random_worlds.h"
#include "world/scene_trace.h"

using namespace engine::world;
using namespace engine::scene;
using namespace gpu_testing;

namespace {

DynamicObject makeObject(glm::ivec3 size, std::uint32_t seed) {
    DynamicObject o;
    o.modelSize = size;
    BrickGrid model(size);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                if ((x * 7 + y * 3 + z * 5 + int(seed)) % 5 != 0)
                    model.set({x, y, z}, MaterialId(1 + (x + y + seed) % 7));
    o.model = std::make_shared<const BrickGrid>(std::move(model));
    return o;
}

// A random world with three rotated objects, one of them half outside the static world.
Scene sceneWithRotatedObjects() {
    Scene scene = gpu_testing::sceneWith(
        testing_worlds::makeWorld(testing_worlds::Kind::Sparse, 21, {64, 48, 64}));
    scene.objects.push_back(makeObject({20, 9, 13}, 1));
    scene.objects.back().current = {{22.3, 17.9, 25.2}, rotationFromYawPitchRoll({31, -17, 52})};
    scene.objects.push_back(makeObject({16, 16, 6}, 2));
    scene.objects.back().current = {{44.0, 30.0, 40.0}, rotationFromAxisAngle({1, 1, 0}, 73)};
    scene.objects.push_back(makeObject({10, 10, 10}, 3));
    scene.objects.back().current = {{62.0, 20.0, 8.0}, rotationFromYawPitchRoll({90, 0, 0})};
    for (DynamicObject& o : scene.objects) o.previous = o.current;
    scene.dynamic = voxelizeObjects(scene.objects);
    scene.dynamic.revision = 1;
    return scene;
}

// A 64x32x64 world with nothing but a floor of material 1.
Scene floorScene() {
    Scene scene = gpu_testing::sceneWith(BrickGrid({64, 32, 64}));
    for (int z = 0; z < 64; ++z)
        for (int x = 0; x < 64; ++x) scene.grid.set({x, 0, z}, 1);
    scene.grid.clearDirty();
    return scene;
}

}  // namespace

class DynamicObjects : public GpuTest {};

TEST_F(DynamicObjects, GpuTraceSceneMatchesTheCpuHitForHit) {
    Scene scene = sceneWithRotatedObjects();
    ASSERT_TRUE(scene.dynamic.present());
    std::vector<Ray> rays = testing_worlds::makeRays(scene.grid, 17, 30000);
    // And rays aimed at the objects, from anywhere around the world.
    engine::Rng rng(5);
    glm::vec3 lo(scene.dynamic.origin),
        hi(scene.dynamic.origin + scene.dynamic.grid.sizeInVoxels());
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 target(rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z));
        glm::vec3 origin(rng.uniform(-10, 74), rng.uniform(-10, 58), rng.uniform(-10, 74));
        glm::vec3 d = target - origin;
        if (glm::length(d) < 1e-3f) continue;
        rays.push_back(
            Ray{origin, glm::normalize(d), i % 7 == 0 ? rng.uniform(1.0f, 40.0f) : 1.0e30f});
    }
    std::vector<shared::TraceRayOutput> gpu =
        gpu_testing::traceOnGpu(scene, rays, shared::TRACE_MODE_SCENE);
    int hits = 0, dynamicHits = 0, mismatches = 0, exactT = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& r = rays[i];
        SceneHit cpu = traceScene(scene.grid, &scene.dynamic, r.origin, r.direction, r.tMax);
        const shared::TraceRayOutput& g = gpu[i];
        bool gpuHit = (g.data.x & 1u) != 0, gpuDynamic = (g.data.x & 2u) != 0;
        float gpuT = glm::uintBitsToFloat(g.data.z);
        hits += cpu.hit;
        dynamicHits += cpu.dynamicSet;
        bool same = gpuHit == cpu.hit &&
                    (!cpu.hit ||
                     (glm::ivec3(g.voxel) == cpu.voxel && std::uint32_t(g.voxel.w) == cpu.face &&
                      g.data.y == cpu.material && gpuDynamic == cpu.dynamicSet));
        if (same) {
            exactT += !cpu.hit || (gpuT == cpu.t && g.data.w == cpu.steps);
            continue;
        }
        ++mismatches;
        EXPECT_LT(testing_worlds::nearestEdgeDistance(r, (cpu.hit ? cpu.t : 0.0f) + 100.0f), 1e-3f)
            << "ray " << i << ": a mismatch that is not a grazing case; cpu " << cpu.hit << "/"
            << cpu.dynamicSet << " " << cpu.voxel.x << "," << cpu.voxel.y << "," << cpu.voxel.z
            << " gpu " << gpuHit << "/" << gpuDynamic << " " << g.voxel.x << "," << g.voxel.y << ","
            << g.voxel.z;
    }
    std::printf(
        "traceScene GPU vs CPU: %zu rays, %d hits, %d on objects, %d mismatches, %d with identical "
        "t and steps\n",
        rays.size(), hits, dynamicHits, mismatches, exactT);
    EXPECT_GT(dynamicHits, int(rays.size()) / 10) << "the objects are in the way of many rays";
    EXPECT_LE(mismatches * 10000, int(rays.size())) << "more than 0.01% of rays disagree";
    EXPECT_GE(exactT, int(rays.size()) - mismatches - int(rays.size()) / 1000);
}

TEST_F(DynamicObjects, StaticPathIsUnchangedWithoutObjects) {
    // With no objects traceScene is the plain static traversal, to the bit.
    Scene scene = gpu_testing::sceneWith(
        testing_worlds::makeWorld(testing_worlds::Kind::Sparse, 4, {48, 40, 56}));
    std::vector<Ray> rays = testing_worlds::makeRays(scene.grid, 3, 5000);
    auto scene_ = gpu_testing::traceOnGpu(scene, rays, shared::TRACE_MODE_SCENE);
    auto plain = gpu_testing::traceOnGpu(scene, rays, shared::TRACE_MODE_HIERARCHICAL);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        ASSERT_EQ(scene_[i].voxel, plain[i].voxel) << i;
        ASSERT_EQ(scene_[i].data, plain[i].data) << i;
    }
}

TEST_F(DynamicObjects, MotionVectorsFollowAMovingObject) {
    // A still camera looks at a turning, moving block: each pixel on it must point to where the
    // CPU says that material point was one frame earlier.
    Scene scene = floorScene();
    DynamicObject o = makeObject({12, 8, 10}, 4);
    o.path = ObjectPath({{0.0, {24, 10, 30}, rotationFromYawPitchRoll({0, 0, 0})},
                         {1.0, {40, 12, 34}, rotationFromYawPitchRoll({60, 10, 0})}},
                        false);
    scene.objects.push_back(std::move(o));
    CameraPreset camera{"test", {32, 24, -10}, {32, 10, 32}, 60.0f};
    FrameSettings settings = frame(96, 64);
    Renderer renderer(gpu_testing::context());
    settings.timeSeconds = 0.4;
    renderer.render(scene, camera, settings, kPreview);
    settings.timeSeconds = 0.45;
    renderer.render(scene, camera, settings, kPreview);
    FrameImages img = renderer.readback();
    const DynamicInstance& inst = scene.dynamic.instances.at(0);
    ASSERT_EQ(scene.objects[0].previous, scene.objects[0].path.at(0.4));
    ASSERT_EQ(scene.objects[0].current, scene.objects[0].path.at(0.45));
    shared::FrameParams f = engine::render::makeFrameParams(camera, scene.sky, settings);
    int onObject = 0, moved = 0;
    double worst = 0.0;
    for (std::uint32_t y = 0; y < settings.height; ++y)
        for (std::uint32_t x = 0; x < settings.width; ++x) {
            const shared::GBufferTexel& g = img.gbuffer[x + y * settings.width];
            // The flag and the world voxel agree with the CPU trace of the same ray.
            glm::vec3 dir = engine::render::cameraRayDirection(f, {x, y});
            SceneHit cpu = traceScene(scene.grid, &scene.dynamic, camera.position, dir, 1.0e30f);
            bool dynamicFlag = (g.data.w & shared::GBUFFER_FLAG_DYNAMIC) != 0;
            if (cpu.hit && glm::ivec3(g.voxel) == cpu.voxel) {
                EXPECT_EQ(dynamicFlag, cpu.dynamicSet) << x << "," << y;
            }
            if (!dynamicFlag) continue;
            ++onObject;
            EXPECT_NE(scene.dynamic.get(glm::ivec3(g.voxel)), kEmpty)
                << "voxel is in world coordinates";
            ASSERT_EQ(g.motion.w, 1.0f);
            // The CPU's answer: the same material point one frame earlier, seen by the same camera.
            glm::dvec3 p(g.position);
            glm::dvec3 prev(inst.prevFromCurrent() * glm::dvec4(p, 1.0));
            glm::dvec3 rel = prev - glm::dvec3(camera.position);
            glm::dvec3 fw(f.cameraForward), rt(f.cameraRight), up(f.cameraUp);
            double z = glm::dot(rel, fw), tanHalf = f.cameraPosition.w, aspect = f.cameraForward.w;
            glm::dvec2 ndc(glm::dot(rel, rt) / (z * tanHalf * aspect),
                           -glm::dot(rel, up) / (z * tanHalf));
            glm::dvec2 expected = (ndc * 0.5 + 0.5) * glm::dvec2(settings.width, settings.height);
            double err = glm::length(expected - glm::dvec2(g.motion.x, g.motion.y));
            worst = std::max(worst, err);
            EXPECT_LT(err, 0.05) << "pixel " << x << "," << y;
            moved += glm::length(glm::dvec2(x + 0.5, y + 0.5) - expected) > 0.5;
        }
    std::printf(
        "motion vectors: %d object pixels, %d moved by more than half a pixel, worst error %.4f "
        "px\n",
        onObject, moved, worst);
    EXPECT_GT(onObject, 100);
    EXPECT_GT(moved, onObject / 2) << "the object does move between the frames";
}

TEST_F(DynamicObjects, ObjectsCastShadows) {
    // Sun straight down on a floor; a slab hovering above it darkens the floor under it.
    Scene scene = floorScene();
    scene.sky.sunDirection = glm::vec3(0, 1, 0);
    DynamicObject o = makeObject({16, 2, 16}, 0);
    BrickGrid slab = *o.model;
    for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) slab.set({x, 0, z}, 2), slab.set({x, 1, z}, 2);
    o.model = std::make_shared<const BrickGrid>(std::move(slab));
    o.path = ObjectPath({{0.0, {32, 20, 32}, {}}}, false);
    scene.objects.push_back(std::move(o));
    CameraPreset camera{"top", {32, 31, 32.01f}, {32, 0, 32}, 100.0f};
    // Looking from below the slab's height, at the floor under it and around it.
    CameraPreset under{"under", {32, 10, 4}, {32, 1, 32}, 70.0f};
    FrameImages img = renderOnce(scene, under, frame(64));
    int shadowed = 0, floorUnder = 0, floorOpen = 0;
    double openSum = 0.0;
    std::vector<float> underRadiance;
    for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
        const shared::GBufferTexel& g = img.gbuffer[i];
        if (g.voxel.w != int(shared::FACE_POS_Y) || g.voxel.y != 0) continue;
        bool below = g.voxel.x >= 24 && g.voxel.x < 40 && g.voxel.z >= 24 && g.voxel.z < 40;
        bool open = g.voxel.x < 20 || g.voxel.x >= 44 || g.voxel.z < 20 || g.voxel.z >= 44;
        if (below) {
            ++floorUnder;
            underRadiance.push_back(img.radiance[i].x);
            shadowed += img.rayStats[i].y > 0;  // a shadow ray was traced (and found the slab)
        } else if (open) {
            ++floorOpen;
            openSum += img.radiance[i].x;
        }
    }
    ASSERT_GT(floorUnder, 50);
    ASSERT_GT(floorOpen, 50);
    EXPECT_EQ(shadowed, floorUnder);
    for (float r : underRadiance)
        EXPECT_LT(r, 0.5 * openSum / floorOpen) << "the floor under the slab is in its shadow";
    (void)camera;
}

TEST_F(DynamicObjects, ShippedWorldsRenderWithTheirObjects) {
    for (const char* name : {"dragon_city.toml", "factory.toml", "thin_wall.toml"}) {
        Scene scene = loadWorld(name);
        ASSERT_FALSE(scene.objects.empty()) << name;
        FrameSettings settings = frame(64, 40);
        Renderer renderer(gpu_testing::context());
        int dynamicPixels = 0;
        for (double t : {0.0, 1.0}) {
            settings.timeSeconds = t;
            renderer.render(scene, scene.camera(), settings, kPreview);
            FrameImages img = renderer.readback();
            for (const auto& g : img.gbuffer)
                dynamicPixels += (g.data.w & shared::GBUFFER_FLAG_DYNAMIC) != 0;
        }
        EXPECT_GT(dynamicPixels, 0) << name << ": its objects are in view of its first camera";
    }
}

// The dynamic grid is one texel view too: objects whose grid would not fit it are refused with
// the count and the device's limit (lowered for the test below the objects' grid, above the
// static floor's texels: one brick page's masks and the top grid's first 8 cell pages, 114 693).
TEST_F(DynamicObjects, AGridOverTheTexelLimitIsRefusedWithItsSize) {
    Scene scene = floorScene();
    DynamicObject o = makeObject({128, 40, 128}, 5);
    o.path = ObjectPath({{0.0, {32, 30, 32}, rotationFromYawPitchRoll({0, 0, 0})}}, false);
    scene.objects.push_back(std::move(o));
    Renderer renderer(gpu_testing::context());
    gpu_testing::context().limitTexelBuffers(200000);
    try {
        renderer.render(scene, {"test", {32, 24, -10}, {32, 10, 32}, 60.0f}, frame(32, 32),
                        kPreview);
        ADD_FAILURE() << "no error";
    } catch (const engine::gpu::TexelBufferTooLarge& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "the dynamic objects' grid too large for the GPU's texel buffer: "),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find(" texels, limit 200000"), std::string::npos)
            << e.what();
    }
    gpu_testing::context().limitTexelBuffers(0);  // the device's
    // The refused grid was not taken for uploaded: with the limit back, the next frame sends it.
    auto again = renderer.render(scene, {"test", {32, 24, -10}, {32, 10, 32}, 60.0f}, frame(32, 32),
                                 kPreview);
    EXPECT_GT(again.upload.dynamicBytes, 0u);
}

// An object's voxels shadow the light-sampling pass's rays exactly as the same voxels would in
// the static world: the sandbox's cart, by every light once (brute force, 1930 lamps and windows),
// against a copy of the world with the cart baked into the static grid. traceScene gives both the
// same hits (SceneTrace tests), so the radiance must match pixel for pixel. Before brute force
// split its emitters across dispatches, 404 of 1536 pixels differed: Mesa 22.3's gallivm gives a
// SIMD batch one budget of 65535 loop passes shared by every loop of the shader
// (LP_MAX_TGSI_LOOP_ITERATIONS), brute force over this many lights spent it, after which every
// loop (a traversal too) made one pass at most, and the two worlds spent it differently
// (docs/PERFORMANCE.md, "Lavapipe's loop budget").
TEST_F(DynamicObjects, LightSamplingSeesAnObjectAsTheStaticWorldWould) {
    Scene moving = loadWorld("sandbox.toml");
    ASSERT_TRUE(moving.dynamic.present());
    Scene baked = loadWorld("sandbox.toml");
    const DynamicGrid& dyn = moving.dynamic;
    const glm::ivec3 size = dyn.grid.sizeInVoxels();
    int cartVoxels = 0;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::ivec3 w = glm::ivec3(x, y, z) + dyn.origin;
                const MaterialId m = dyn.get(w);
                if (m == kEmpty || baked.grid.get(w) != kEmpty) continue;  // static wins ties
                baked.grid.set(w, m);
                ++cartVoxels;
            }
    ASSERT_GT(cartVoxels, 100);
    baked.objects.clear();
    baked.dynamic = DynamicGrid{};
    LightingSettings brute{Method::BruteForce};
    brute.display.mode =
        engine::lighting::Display::Raw;  // the light-sampling pass's radiance, not denoised
    FrameSettings settings = frame(48, 32);
    FrameImages a = renderOnce(moving, moving.camera(), settings, brute);
    FrameImages b = renderOnce(baked, baked.camera(), settings, brute);
    ASSERT_EQ(a.radiance.size(), b.radiance.size());
    int differ = 0;
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.radiance.size(); ++i) {
        const glm::vec3 d = glm::abs(glm::vec3(a.radiance[i]) - glm::vec3(b.radiance[i]));
        const glm::vec3 r(b.radiance[i]);
        const float rel = std::max({d.x, d.y, d.z}) / (std::max({r.x, r.y, r.z}) + 1e-6f);
        differ += rel > 1e-5f;
        worst = std::max(worst, rel);
    }
    std::printf("light sampling, cart as an object vs baked: %d of %zu pixels differ (worst %g)\n",
                differ, a.radiance.size(), worst);
    EXPECT_EQ(differ, 0);
}
