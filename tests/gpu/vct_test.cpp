// Voxel cone tracing (`--indirect vct`, render/vct/): the cheap, leaky indirect term. Its mean
// against the path tracer's indirect light on an open scene (loose: the cones are a coarse,
// biased estimate), its leak through a one-voxel wall with the leak mitigation on (bounded) and
// off (large), and its determinism.
#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <tuple>

#include "gpu/gpu_test_setup.h"
#include "render/vct/voxel_cone_tracing.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
using engine::lighting::Indirect;

namespace {

constexpr MaterialId kWhite = 1, kRed = 2, kLamp = 3, kGreen = 4;

Scene makeScene(glm::ivec3 size) {
    return paletteScene(
        size,
        {Material{"white", glm::vec3(0.75f)}, Material{"red", glm::vec3(0.8f, 0.15f, 0.1f)},
         Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 8.0f},
         Material{"green", glm::vec3(0.1f, 0.7f, 0.2f)}},
        false);
}

// The path-indirect test's open courtyard: a floor, a red and a green wall, a pillar, a lamp,
// under sun and sky.
Scene courtyard() {
    Scene scene = makeScene({32, 24, 32});
    fillBox(scene.grid, Box{{0, 0, 0}, {32, 2, 32}}, kWhite);
    fillBox(scene.grid, Box{{0, 2, 26}, {32, 16, 28}}, kRed);
    fillBox(scene.grid, Box{{26, 2, 0}, {28, 16, 26}}, kGreen);
    fillBox(scene.grid, Box{{12, 2, 12}, {15, 10, 15}}, kWhite);
    fillBox(scene.grid, Box{{5, 6, 20}, {7, 8, 22}}, kLamp);
    scene.sky.sunDirection = glm::normalize(glm::vec3(-0.5f, 1.0f, -0.6f));
    scene.cameras.push_back(
        CameraPreset{"corner", {4.0f, 14.0f, 3.0f}, {23.0f, 3.0f, 22.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

// The irradiance cache's thin-wall scene (IrradianceCache.ThinWallDoesNotLeak): a sealed, unlit
// room with one-voxel walls and roof, the sun and a lamp outside.
Scene thinWallRoom() {
    Scene scene = makeScene({48, 32, 48});
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 4, 48}}, kWhite);
    fillBox(scene.grid, Box{{23, 4, 7}, {41, 20, 41}}, kWhite);
    fillBox(scene.grid, Box{{24, 4, 8}, {40, 19, 40}}, 0);
    fillBox(scene.grid, Box{{12, 10, 20}, {14, 12, 22}}, kLamp);
    scene.cameras.push_back(
        CameraPreset{"inside", {38.0f, 16.0f, 24.0f}, {24.0f, 6.0f, 24.0f}, 80.0f});
    scene.cameras.push_back(
        CameraPreset{"outside", {4.0f, 16.0f, 24.0f}, {23.0f, 6.0f, 24.0f}, 80.0f});
    scene.grid.clearDirty();
    return scene;
}

LightingSettings vctLighting(bool leakMitigation = true) {
    LightingSettings l;
    l.method = Method::Preview;  // only the indirect term is compared
    l.indirect = Indirect::Vct;
    l.vct.leakMitigation = leakMitigation;
    return l;
}

double meanOf(const std::vector<glm::vec4>& img) {
    double sum = 0.0;
    for (const glm::vec4& p : img) sum += (p.x + p.y + p.z) / 3.0;
    return sum / double(img.size());
}

// The path tracer's one-bounce indirect light through the pixel centres: (1 bounce) - (direct).
std::vector<glm::vec4> referenceIndirect(Scene& scene, const CameraPreset& camera,
                                         std::uint32_t size, std::uint32_t spp) {
    auto run = [&](std::uint32_t bounces) {
        Renderer r(gpu_testing::context());
        LightingSettings l;
        l.method = Method::Reference;
        l.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
        l.bounces = bounces;
        l.samplesPerFrame = 32;
        for (std::uint32_t i = 0; i < spp / 32; ++i) r.render(scene, camera, frame(size), l);
        return r.readback().radiance;
    };
    std::vector<glm::vec4> with = run(1), without = run(0);
    for (std::size_t i = 0; i < with.size(); ++i) with[i] -= without[i];
    return with;
}

// A street longer than levels 0 and 1 reach (64 and 128 voxels), so they move with a camera
// walking it: a floor, walls of two colours every 16 voxels, a lamp, the sun — and a 6^3 block
// sliding 50 voxels along it in the first scene second.
Scene street() {
    Scene scene = makeScene({224, 24, 40});
    fillBox(scene.grid, Box{{0, 0, 0}, {224, 2, 40}}, kWhite);
    for (int x = 8; x < 224; x += 16)
        fillBox(scene.grid, Box{{x, 2, 30}, {x + 3, 14, 36}}, (x / 16) % 2 ? kRed : kGreen);
    fillBox(scene.grid, Box{{100, 8, 10}, {102, 10, 12}}, kLamp);
    scene.grid.clearDirty();
    DynamicObject block;
    block.modelSize = glm::ivec3(6);
    BrickGrid model(block.modelSize);
    fillBox(model, Box{glm::ivec3(0), block.modelSize}, kWhite);
    block.model = std::make_shared<const BrickGrid>(std::move(model));
    block.path =
        ObjectPath({ObjectKey{0.0, {40.0, 6.0, 18.0}}, ObjectKey{1.0, {90.0, 6.0, 18.0}}}, false);
    scene.objects.push_back(block);
    return scene;
}

// The doorway-lit room: a closed room (48 x 24 x 48 voxels inside) with walls and roof
// `wall` voxels thick, lit only through a doorway in its -x wall by a low sun (and the sky);
// camera "ceiling" inside looks straight up at the ceiling, which only light bounced off the
// sunlit patch of floor inside (and the walls) reaches.
Scene doorwayRoom(int wall) {
    Scene scene = makeScene({112, 48, 112});
    fillBox(scene.grid, Box{{0, 0, 0}, {112, 2, 112}}, kWhite);
    fillBox(scene.grid, Box{{32 - wall, 2, 32 - wall}, {80 + wall, 26 + wall, 80 + wall}}, kWhite);
    fillBox(scene.grid, Box{{32, 2, 32}, {80, 26, 80}}, 0);
    fillBox(scene.grid, Box{{32 - wall, 2, 48}, {32, 18, 64}}, 0);  // the doorway
    scene.sky.sunDirection = glm::normalize(glm::vec3(-1.0f, 0.7f, 0.0f));
    scene.cameras.push_back(
        CameraPreset{"ceiling", {60.0f, 6.0f, 56.0f}, {60.0f, 26.0f, 56.5f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

}  // namespace

class Vct : public GpuTest {};

// On an open courtyard the cones' mean is between 0.5 and 1.5 times the path tracer's one-bounce
// indirect mean (measured 0.88; 0.66 while the cones met their own surface, docs/ACCURACY.md).
// Loose on purpose: the cones see the world through 2..16-voxel texels; what the test pins is that
// the term has the right size (a lost factor of pi, a missing sky or no occlusion at all would be
// far outside it).
TEST_F(Vct, MeanNearPathTracerOnAnOpenScene) {
    Scene scene = courtyard();
    const std::uint32_t size = 24;  // small and 128 spp: the test stays within seconds
    const std::vector<glm::vec4> ref = referenceIndirect(scene, scene.camera(), size, 128);
    Renderer r(gpu_testing::context());
    const std::vector<glm::vec4> vct =
        renderFrames(r, scene, vctLighting(), frame(size), 1).indirect;
    const double ratio = meanOf(vct) / meanOf(ref);
    std::printf("courtyard: vct indirect mean %.5f, path tracer %.5f (ratio %.3f), MAE %.5f\n",
                meanOf(vct), meanOf(ref), ratio, mae(vct, ref));
    EXPECT_GT(meanOf(ref), 0.01);
    EXPECT_GT(ratio, 0.5);
    EXPECT_LT(ratio, 1.5);
}

// Inside a sealed room with one-voxel walls the true indirect light is 0 (the cache's figure).
// VCT leaks: texels 2..16 voxels wide hold both sides of the wall, and a cone's trilinear samples
// reach past a wall before its opacity adds up. With the mitigation (directional texels, the
// largest axis coverage as opacity, cones started off the surface) the inside's mean indirect
// light stays under 45 % of the lit side's (measured 34 %); without it, it is over 2.5 times
// that (measured 3.2 times).
TEST_F(Vct, ThinWallLeakIsBoundedWithMitigationOnly) {
    Scene scene = thinWallRoom();
    auto indirectFrom = [&](const char* camera, bool mitigation) {
        Renderer r(gpu_testing::context());
        r.render(scene, scene.camera(camera), frame(48), vctLighting(mitigation));
        return r.readback().indirect;
    };
    const double outside = meanOf(indirectFrom("outside", true));
    const double leak = meanOf(indirectFrom("inside", true));
    const double leakWithout = meanOf(indirectFrom("inside", false));
    std::printf(
        "thin wall: indirect outside mean %.4f; inside mean %.5f with leak mitigation (%.2f %%), "
        "%.5f without (%.2f %%)\n",
        outside, leak, 100.0 * leak / outside, leakWithout, 100.0 * leakWithout / outside);
    EXPECT_GT(outside, 0.02);
    EXPECT_LT(leak, 0.45 * outside);
    EXPECT_GT(leakWithout, 2.5 * leak);
}

// Same scene, settings and camera: the same image, from another renderer and on every still
// frame (the injection's jitter is seeded by texel position and seed, not by the frame).
TEST_F(Vct, DeterministicAndStillFramesAreIdentical) {
    Scene scene = courtyard();
    LightingSettings l = vctLighting();
    Renderer a(gpu_testing::context()), b(gpu_testing::context());
    const std::vector<glm::vec4> first = renderFrames(a, scene, l, frame(24), 1).indirect;
    const std::vector<glm::vec4> third = renderFrames(a, scene, l, frame(24), 2).indirect;
    const std::vector<glm::vec4> other = renderFrames(b, scene, l, frame(24), 1).indirect;
    ASSERT_GT(meanOf(first), 0.0);
    EXPECT_EQ(first, third);
    EXPECT_EQ(first, other);
    l.seed = 2;  // and the seed matters
    EXPECT_NE(renderFrames(b, scene, l, frame(24), 1).indirect, first);
}

// An open floor under the sky alone (no sun, no lamp): every direction above it sees the sky, so
// its indirect light is exactly albedo × the sky's cosine-weighted mean, skyRadiance × (1 + 0.4 ×
// 2/3) for the gradient of surface.glsl's skyBackground (radiance × (1 + 0.4 cos θ) about the
// vertical). The six cones' estimate of that mean is skyRadiance × (0.25 × 1.4 + 0.75 × 1.2) =
// 1.25 × skyRadiance, 0.987 of it: the cone approximation's share, seen alone where the floor is
// outside the clipmap (one level, 64 voxels, about a camera 200 voxels up), so no cone meets
// anything. Where the floor is in the clipmap the cones must still see only sky — they used to
// meet their own floor in the texels that hold it (0.36 of the sky's light).
TEST_F(Vct, OpenFloorGathersItsSky) {
    Scene scene = makeScene({128, 16, 128});
    fillBox(scene.grid, Box{{0, 0, 0}, {128, 2, 128}}, kWhite);
    scene.sky.sunRadiance = glm::vec3(0.0f);
    // Low and steep: every pixel sees the floor (no sky pixels, whose indirect term is 0).
    scene.cameras.push_back(
        CameraPreset{"low", {64.0f, 20.0f, 50.0f}, {64.0f, 2.0f, 64.0f}, 60.0f});
    scene.cameras.push_back(
        CameraPreset{"high", {64.0f, 200.0f, 64.0f}, {64.0f, 2.0f, 64.5f}, 20.0f});
    scene.grid.clearDirty();
    const glm::vec3 exact = 0.75f * scene.sky.skyRadiance * (1.0f + 0.4f * 2.0f / 3.0f);
    const double exactMean = (exact.x + exact.y + exact.z) / 3.0;
    auto ratioFrom = [&](const char* camera, std::uint32_t levels) {
        LightingSettings l = vctLighting();
        l.vct.levels = levels;
        Renderer r(gpu_testing::context());
        r.render(scene, scene.camera(camera), frame(24), l);
        return meanOf(r.readback().indirect) / exactMean;
    };
    const double outside = ratioFrom("high", 1), inside = ratioFrom("low", 4);
    std::printf(
        "open floor under the sky: cones / exact %.4f with the floor outside the clipmap (the "
        "cones' "
        "own share: 1.25 / 1.2667 = 0.987), %.4f inside it\n",
        outside, inside);
    EXPECT_NEAR(outside, 1.25 / (1.0 + 0.4 * 2.0 / 3.0), 0.005);
    EXPECT_GT(inside, 0.95);
    EXPECT_LT(inside, 1.01);
}

// The indirect mean against the path tracer's on shipped worlds, printed for docs/ACCURACY.md
// (`ctest -R Vct.ShippedWorlds --output-on-failure`): one bounce and three, the cones with and
// without their extra bounce. Bounds loose enough for the method (its own limits are measured by
// the tests above); what they pin is that the cones reach the rooms at all.
TEST_F(Vct, IndirectMeanAgainstThePathTracerOnShippedWorlds) {
    constexpr std::uint32_t kSize = 32, kSpp = 256;
    for (const char* name : {"cornell", "apartments"}) {
        Scene scene = loadWorld(name);
        auto reference = [&](std::uint32_t bounces) {
            auto run = [&](std::uint32_t b) {
                Renderer r(gpu_testing::context());
                LightingSettings l;
                l.method = Method::Reference;
                l.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
                l.bounces = b;
                l.samplesPerFrame = 32;
                for (std::uint32_t i = 0; i < kSpp / 32; ++i)
                    r.render(scene, scene.camera(), frame(kSize), l);
                return r.readback().radiance;
            };
            std::vector<glm::vec4> with = run(bounces), without = run(0);
            for (std::size_t i = 0; i < with.size(); ++i) with[i] -= without[i];
            return meanOf(with);
        };
        auto cones = [&](bool bounce) {
            LightingSettings l = vctLighting();
            l.vct.extraBounce = bounce;
            Renderer r(gpu_testing::context());
            return meanOf(renderFrames(r, scene, l, frame(kSize), bounce ? 4 : 1).indirect);
        };
        const double one = reference(1), three = reference(3);
        const double vct = cones(false), vctBounce = cones(true);
        std::printf(
            "%s: path tracer indirect mean %.5f (1 bounce), %.5f (3); vct %.5f (%.3f of 1 bounce), "
            "with its extra bounce %.5f (%.3f of 3)\n",
            name, one, three, vct, vct / one, vctBounce, vctBounce / three);
        // Issue 38's acceptance: at least 0.8 of the path tracer's mean, and not far above it.
        // Cornell gave 1.68 while its camera, 380 voxels before the box, left the box out of the
        // camera-centred clipmap (the cones saw only sky, unoccluded).
        EXPECT_GT(vct / one, 0.8) << name;
        EXPECT_LT(vct / one, 1.25) << name;
    }
}

// The block list (render/vct/vct_block_list.h) classifies only the blocks of texels that may have
// changed; every frame must give the image of classifying every texel (`vct_classify_all`), and
// while the world and the objects rest it must classify only the blocks the moving levels bring
// in. A walk along the street: the camera moves (levels 0 and 1 take in new texels, whose slots
// held others) while the block slides, then the camera stops, the block rests, then it is taken
// away (its texels must be zeroed, the shadow it cast re-injected in turn), then the camera walks
// on. In place and with the extra bounce (two volumes, each written every other frame).
TEST_F(Vct, BlockListGivesTheImageOfClassifyingEveryTexel) {
    constexpr std::uint32_t kFrames = 28, kRefresh = 4;
    const auto cameraAt = [](std::uint32_t i) {
        const float x = 10.0f + 12.0f * float(std::min(i, 9u)) + 15.0f * float(i > 22 ? i - 22 : 0);
        return CameraPreset{"walk", {x, 12.0f, 4.0f}, {x + 30.0f, 3.0f, 30.0f}, 70.0f};
    };
    struct Run {
        std::vector<std::vector<glm::vec4>> images;
        std::vector<std::uint32_t> blocks;
    };
    const auto walk = [&](bool bounce, bool classifyAll) {
        Scene scene = street();
        LightingSettings l = vctLighting();
        l.vct.refreshPeriod = kRefresh;
        l.vct.extraBounce = bounce;
        l.vct.classifyAll = classifyAll;
        Renderer r(gpu_testing::context());
        Run run;
        for (std::uint32_t i = 0; i < kFrames; ++i) {
            if (i == 16) scene.objects.clear();
            FrameSettings f = frame(24);
            f.timeSeconds = double(std::min(i, 8u)) / 8.0;  // the block rests from frame 8
            run.blocks.push_back(r.render(scene, cameraAt(i), f, l).vctBlocks);
            run.images.push_back(r.readback().indirect);
        }
        return run;
    };
    for (const bool bounce : {false, true}) {
        const Run all = walk(bounce, true), listed = walk(bounce, false);
        for (std::uint32_t i = 0; i < kFrames; ++i) {
            EXPECT_GT(meanOf(all.images[i]), 0.0) << "frame " << i;
            EXPECT_EQ(listed.images[i], all.images[i]) << "frame " << i << " bounce " << bounce;
            EXPECT_EQ(all.blocks[i], 4 * ::shared::VCT_BLOCKS_PER_LEVEL);
        }
        std::printf("street, %s: blocks classified per frame:",
                    bounce ? "extra bounce" : "in place");
        for (std::uint32_t b : listed.blocks) std::printf(" %u", b);
        std::printf(" (of %u)\n", 4 * ::shared::VCT_BLOCKS_PER_LEVEL);
        if (bounce) continue;
        // In place, once the objects rested kRefresh frames (their grid changes last on frame 9,
        // whose previous pose is the rest pose) and the camera stopped (frame 9): nothing to
        // classify; after the block is taken away (frame 16) its
        // rotation again; the camera walking on brings in blocks of the moving levels only.
        for (std::uint32_t i = 14; i < 16; ++i) EXPECT_EQ(listed.blocks[i], 0u) << "frame " << i;
        EXPECT_GT(listed.blocks[16], 0u);
        for (std::uint32_t i = 20; i < 23; ++i) EXPECT_EQ(listed.blocks[i], 0u) << "frame " << i;
        for (std::uint32_t i = 23; i < kFrames; ++i) {
            EXPECT_GT(listed.blocks[i], 0u) << "frame " << i;
            EXPECT_LE(listed.blocks[i], 2 * ::shared::VCT_BLOCKS_PER_LEVEL) << "frame " << i;
        }
    }
}

// The doorway-lit room of issue 38: the ceiling's indirect light against the path tracer's, with
// walls and roof 1 and 16 voxels thick, one clipmap level (64 voxels: cones leave it inside the
// room) and four (the room inside), under sun and sky and under the sun alone (docs/ACCURACY.md).
// One level under the sky was 5.6 and 13.5 times too bright — thicker walls brighter, so not a
// leak through them: a cone past the clipmap took the sky, right in the open, wrong in a room.
// Now a ray on from the cone's last sample decides (vctBeyondClipmap): 0.60 and 0.22, as under
// the sun alone (0.62, 0.24: the lit floor is past the cones' reach). With the room in the
// clipmap, 1.73 and 1.57 under the sky, 1.57 and 1.02 under the sun alone: the 1-voxel walls leak
// (the method's own, Vct.ThinWallLeak...), and the sky through the doorway, 16 voxels across, seen
// through 8- and 16-voxel texels, is too bright.
TEST_F(Vct, DoorwayLitRoomCeiling) {
    std::map<std::tuple<int, bool, std::uint32_t>, double> ratio;
    for (const int wall : {1, 16}) {
        for (const bool sky : {true, false}) {
            Scene scene = doorwayRoom(wall);
            if (!sky) scene.sky.skyRadiance = glm::vec3(0.0f);
            const CameraPreset camera = scene.camera("ceiling");
            const double ref = meanOf(referenceIndirect(scene, camera, 24, 256));
            for (const std::uint32_t levels : {1u, 4u}) {
                LightingSettings l = vctLighting();
                l.vct.levels = levels;
                Renderer r(gpu_testing::context());
                r.render(scene, camera, frame(24), l);
                const double vct = meanOf(r.readback().indirect);
                std::printf(
                    "doorway room, walls %2d voxels, %s, %u level(s): ceiling indirect vct %.5f, "
                    "path tracer %.5f (ratio %.2f)\n",
                    wall, sky ? "sun and sky" : "sun alone ", levels, vct, ref, vct / ref);
                ratio[std::make_tuple(wall, sky, levels)] = vct / ref;
            }
        }
    }
    const auto at = [&](int wall, bool sky, std::uint32_t levels) {
        return ratio[std::make_tuple(wall, sky, levels)];
    };
    for (const int wall : {1, 16}) {
        EXPECT_LT(at(wall, true, 1u), 1.0) << wall;   // no sky through walls past the clipmap
        EXPECT_LT(at(wall, false, 1u), 1.0) << wall;  // the rest of the light out of reach
        EXPECT_LT(at(wall, true, 4u), 2.0) << wall;
    }
    EXPECT_NEAR(at(16, false, 4u), 1.0, 0.2);  // in reach, no sky, no thin wall
}

// The clipmap's levels (VoxelConeTracing::levelOrigin): a camera deep inside a large world gets
// levels centred on it, as before; one inside a small world stays inside every level; one far
// outside the world (Cornell's preset) gets a coarsest level that covers the whole world — the
// camera-centred levels held none of it.
TEST(VctClipmap, LevelsStayOverTheWorld) {
    using engine::render::VoxelConeTracing;
    const auto covers = [](glm::ivec3 origin, std::uint32_t level, glm::vec3 p) {
        const float extent = float(::shared::VCT_RES * (::shared::VCT_BASE_TEXEL << level));
        return glm::all(glm::greaterThanEqual(p, glm::vec3(origin))) &&
               glm::all(glm::lessThan(p, glm::vec3(origin) + extent));
    };
    const glm::vec3 deep(1000.5f, 700.25f, 1200.0f);
    for (std::uint32_t l = 0; l < ::shared::VCT_MAX_LEVELS; ++l) {
        const int texel = int(::shared::VCT_BASE_TEXEL << l);
        const glm::ivec3 cameraCentred =
            (glm::ivec3(glm::floor(deep / float(texel))) - int(::shared::VCT_RES / 2)) * texel;
        EXPECT_EQ(
            VoxelConeTracing::levelOrigin(deep, l, glm::ivec3(0), glm::ivec3(2048, 2048, 2048)),
            cameraCentred);
        for (const glm::vec3 inside : {glm::vec3(4, 14, 3), glm::vec3(47.5f, 0, 20), glm::vec3(0)})
            EXPECT_TRUE(
                covers(VoxelConeTracing::levelOrigin(inside, l, glm::ivec3(0), glm::ivec3(48)), l,
                       inside));
    }
    const glm::vec3 cornellCamera(136, 136, -380);
    const glm::ivec3 coarsest =
        VoxelConeTracing::levelOrigin(cornellCamera, 3, glm::ivec3(0), glm::ivec3(272));
    EXPECT_TRUE(covers(coarsest, 3, glm::vec3(0.0f)));
    EXPECT_TRUE(covers(coarsest, 3, glm::vec3(271.9f)));
}
