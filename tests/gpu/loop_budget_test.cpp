// Lavapipe's loop budget (engine/render/loop_budget.h): the shaders whose loops can spend a SIMD
// batch's 65 535 passes split their work across dispatches, and the split changes no bit of what
// one dispatch far below the budget computes. Each test's world is built to spend the budget in
// one dispatch, and checks that it does (else it would show nothing); the reference's corridor is
// checked only against one sample per frame.
#include "render/loop_budget.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <gtest/gtest.h>

#include "core/hash.h"
#include "gpu/gpu_test_setup.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
namespace render = engine::render;

namespace {

int differingPixels(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    int differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        differ += std::memcmp(&a[i], &b[i], sizeof(glm::vec4)) != 0;
    return differ;
}

// A corridor 16 voxels wide and high and 384 long, its walls rough (one voxel in three sticks
// out), no cell of it empty, lamps along its ceiling and a dark sky: rays along it cross hundreds
// of voxels one small block at a time.
Scene corridor() {
    const glm::ivec3 size{16, 16, 384};
    Scene scene =
        paletteScene(size,
                     {Material{"white", glm::vec3(0.7f)},
                      Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.9f, 0.7f), 8.0f}},
                     true);
    const MaterialId white = *scene.palette.find("white"), lamp = *scene.palette.find("lamp");
    fillBox(scene.grid, Box{{0, 0, 0}, {16, 1, 384}}, white);
    fillBox(scene.grid, Box{{0, 15, 0}, {16, 16, 384}}, white);
    fillBox(scene.grid, Box{{0, 0, 0}, {1, 16, 384}}, white);
    fillBox(scene.grid, Box{{15, 0, 0}, {16, 16, 384}}, white);
    fillBox(scene.grid, Box{{0, 0, 383}, {16, 16, 384}}, white);
    for (int z = 0; z < size.z; ++z)
        for (int y = 1; y < 15; ++y)
            for (int x = 1; x < 15; ++x) {
                const bool wall = x == 1 || x == 14 || y == 1 || y == 14;
                if (wall && engine::pcgHash(std::uint32_t(x + 16 * y + 256 * z)) % 3u == 0u)
                    scene.grid.set({x, y, z}, white);
            }
    for (int z = 8; z < size.z; z += 12) scene.grid.set({7 + z % 2, 14, z}, lamp);
    scene.cameras.push_back(
        CameraPreset{"down the corridor", {8.0f, 8.0f, 2.0f}, {8.0f, 7.0f, 200.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

}  // namespace

class LoopBudget : public GpuTest {};

// The sandbox's 1 930 emitters in one dispatch spend a SIMD batch's 65 535 loop passes, and the
// shadow rays after that are cut (docs/PERFORMANCE.md, "Lavapipe's loop budget"); in ranges sized
// by the budget the image is bit for bit the one of four emitters per dispatch, far below it.
TEST_F(LoopBudget, BruteForceSumsEveryEmitter) {
    Scene scene = loadWorld("sandbox.toml");
    const std::uint32_t perDispatch = render::shadowRaysPerDispatch(scene);
    std::printf("sandbox: %u loop passes per ray at most, %u shadow rays per dispatch\n",
                render::rayLoopPasses(scene), perDispatch);
    LightingSettings brute{Method::BruteForce};
    brute.display.mode = engine::lighting::Display::Raw;
    const FrameSettings settings = frame(32, 24);
    FrameImages budget = renderOnce(scene, scene.camera(), settings, brute);
    brute.shadowRaysPerDispatch = 4;
    FrameImages small = renderOnce(scene, scene.camera(), settings, brute);
    brute.shadowRaysPerDispatch = 1u << 30;  // one dispatch, as before the split
    FrameImages whole = renderOnce(scene, scene.camera(), settings, brute);
    ASSERT_EQ(budget.radiance.size(), small.radiance.size());
    const int cut = differingPixels(whole.radiance, small.radiance);
    std::printf("brute force, one dispatch vs 4 emitters per dispatch: %d of %zu pixels differ\n",
                cut, small.radiance.size());
    EXPECT_GT(cut, 0) << "the world no longer spends the budget: the test shows nothing";
    EXPECT_EQ(differingPixels(budget.radiance, small.radiance), 0);
}

// 2 048 uniform light samples per pixel on the sandbox: split by the budget, the same image as 8
// samples per dispatch.
TEST_F(LoopBudget, UniformSamplesSumEverySample) {
    Scene scene = loadWorld("sandbox.toml");
    LightingSettings uniform{Method::Uniform};
    uniform.shadowRays = 2048;
    uniform.display.mode = engine::lighting::Display::Raw;
    const FrameSettings settings = frame(32, 24);
    FrameImages budget = renderOnce(scene, scene.camera(), settings, uniform);
    uniform.shadowRaysPerDispatch = 8;
    FrameImages small = renderOnce(scene, scene.camera(), settings, uniform);
    uniform.shadowRaysPerDispatch = 1u << 30;
    FrameImages whole = renderOnce(scene, scene.camera(), settings, uniform);
    const int cut = differingPixels(whole.radiance, small.radiance);
    std::printf("uniform 2048 samples, one dispatch vs 8 per dispatch: %d of %zu pixels differ\n",
                cut, small.radiance.size());
    EXPECT_GT(cut, 0) << "the world no longer spends the budget: the test shows nothing";
    EXPECT_EQ(differingPixels(budget.radiance, small.radiance), 0);
}

// The reference path tracer down the corridor, 32 samples per pixel and 3 bounces in one frame
// (bench flythrough's and the display bench's samples per frame): the same sums as 32 frames of
// one sample, each far below the budget (a sample's random numbers follow from the pixel's
// sample count, so frames and dispatches may split the samples anyhow).
TEST_F(LoopBudget, ReferenceSamplesAreThoseOfOneSamplePerFrame) {
    Scene scene = corridor();
    LightingSettings ref{Method::Reference};
    ref.bounces = 3;
    ref.samplesPerFrame = 32;
    std::printf("corridor: %u loop passes per path sample at most, %u samples per dispatch\n",
                render::pathSampleLoopPasses(scene, ref.bounces),
                render::referenceSamplesPerDispatch(scene, ref.bounces));
    const FrameSettings settings = frame(24, 16);
    Renderer once(gpu_testing::context());
    FrameImages a = renderFrames(once, scene, ref, settings, 1);
    ref.samplesPerFrame = 1;
    Renderer many(gpu_testing::context());
    FrameImages b = renderFrames(many, scene, ref, settings, 32);
    ASSERT_EQ(a.radiance.size(), b.radiance.size());
    const int differ = differingPixels(a.radiance, b.radiance);
    std::printf("reference, 32 samples in one frame vs 32 frames of one: %d of %zu pixels differ\n",
                differ, a.radiance.size());
    EXPECT_EQ(differ, 0);
}
