// The path-traced indirect term (`--indirect path`, render/path_indirect/): its mean against the
// reference path tracer's indirect light (with bounces minus without), and its accumulation —
// a running mean over still frames that restarts when the camera moves.
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "gpu/sample_stats.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
using engine::lighting::Indirect;

namespace {

// An open courtyard under sun and sky with one lamp: a floor, a red and a green wall, a pillar.
// Its indirect light is sun, sky and lamp bouncing off coloured surfaces.
Scene courtyard() {
    Scene scene = paletteScene(
        {32, 24, 32},
        {Material{"white", glm::vec3(0.75f)}, Material{"red", glm::vec3(0.8f, 0.15f, 0.1f)},
         Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 8.0f},
         Material{"green", glm::vec3(0.1f, 0.7f, 0.2f)}},
        false);
    const MaterialId white = 1, red = 2, lamp = 3, green = 4;
    fillBox(scene.grid, Box{{0, 0, 0}, {32, 2, 32}}, white);
    fillBox(scene.grid, Box{{0, 2, 26}, {32, 16, 28}}, red);
    fillBox(scene.grid, Box{{26, 2, 0}, {28, 16, 26}}, green);
    fillBox(scene.grid, Box{{12, 2, 12}, {15, 10, 15}}, white);
    fillBox(scene.grid, Box{{5, 6, 20}, {7, 8, 22}}, lamp);
    scene.sky.sunDirection = glm::normalize(glm::vec3(-0.5f, 1.0f, -0.6f));
    scene.cameras.push_back(
        CameraPreset{"corner", {4.0f, 14.0f, 3.0f}, {23.0f, 3.0f, 22.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

LightingSettings pathLighting(std::uint32_t samples, std::uint32_t bounces, std::uint32_t seed,
                              bool accumulate = true) {
    LightingSettings l;
    l.method = Method::Preview;  // only the indirect term is compared
    l.indirect = Indirect::Path;
    l.path.samples = samples;
    l.path.bounces = bounces;
    l.path.accumulate = accumulate;
    l.seed = seed;
    return l;
}

double meanOf(const std::vector<glm::vec4>& img) {
    double sum = 0.0;
    for (const glm::vec4& p : img) sum += (p.x + p.y + p.z) / 3.0;
    return sum / double(img.size());
}

// The reference's indirect light through the pixel centres: (bounces) minus (direct only), by
// two renderers the caller keeps (new settings restart their accumulation; a renderer is slow
// to make on a CPU device).
std::vector<glm::vec4> referenceIndirect(Renderer& with, Renderer& without, Scene& scene,
                                         std::uint32_t size, std::uint32_t bounces,
                                         std::uint32_t spp, std::uint32_t seed) {
    auto run = [&](Renderer& r, std::uint32_t b) {
        LightingSettings l;
        l.method = Method::Reference;
        l.referenceFilter =
            engine::lighting::ReferenceFilter::PixelCentre;  // the G-buffer's pixels
        l.bounces = b;
        l.seed = seed;
        l.samplesPerFrame = 32;
        return renderFrames(r, scene, l, frame(size), int(spp / 32)).radiance;
    };
    std::vector<glm::vec4> result = run(with, bounces), direct = run(without, 0);
    for (std::size_t i = 0; i < result.size(); ++i) result[i] -= direct[i];
    return result;
}

}  // namespace

class PathIndirect : public GpuTest {};

// The term is unbiased: over independent seeds, the mean of its image agrees with the mean of
// the reference's indirect image within four standard errors of the difference (a false alarm
// about once in 16 000 runs; the seeds are fixed, so the outcome is too). One bounce, and three
// (the walk past the first bounce, Russian roulette from the third).
TEST_F(PathIndirect, MeanMatchesReferenceIndirect) {
    Scene scene = courtyard();
    constexpr std::uint32_t kSize = 24, kSpp = 64, kSeeds = 3;
    Renderer r(gpu_testing::context()), with(gpu_testing::context()),
        without(gpu_testing::context());
    for (std::uint32_t bounces : {1u, 3u}) {
        std::vector<double> path, reference;
        for (std::uint32_t seed = 1; seed <= kSeeds; ++seed) {
            // A still camera: 4 frames of 16 paths accumulate to 64 per pixel (new settings
            // restart).
            path.push_back(meanOf(
                renderFrames(r, scene, pathLighting(16, bounces, seed), frame(kSize), 4).indirect));
            reference.push_back(
                meanOf(referenceIndirect(with, without, scene, kSize, bounces, kSpp, 100 + seed)));
        }
        const MeanAndError p = meanOfMeans(path), ref = meanOfMeans(reference);
        const double sigma =
            std::sqrt(p.standardError * p.standardError + ref.standardError * ref.standardError);
        std::printf(
            "%u bounce(s): path indirect mean %.5f +- %.5f, reference %.5f +- %.5f (%+.2f %%)\n",
            bounces, p.mean, p.standardError, ref.mean, ref.standardError,
            100.0 * (p.mean / ref.mean - 1.0));
        EXPECT_GT(ref.mean, 0.01) << "the scene must have indirect light to compare";
        EXPECT_LT(std::abs(p.mean - ref.mean), 4.0 * sigma) << bounces << " bounce(s)";
        // And the test can tell: the standard error is small against the mean.
        EXPECT_LT(sigma, 0.02 * ref.mean) << bounces << " bounce(s)";
    }
}

// On a still camera a frame shows the mean of every path so far: the same as averaging the
// single frames that accumulation off draws with the same seeds (frame index and path number).
TEST_F(PathIndirect, StillCameraAccumulatesTheFramesPaths) {
    Scene scene = courtyard();
    constexpr int kFrames = 4;
    Renderer accumulated(gpu_testing::context());
    const std::vector<glm::vec4> mean =
        renderFrames(accumulated, scene, pathLighting(2, 1, 7), frame(16), kFrames).indirect;
    std::vector<glm::vec4> sum(mean.size(), glm::vec4(0.0f));
    Renderer single(gpu_testing::context());
    for (int i = 0; i < kFrames; ++i) {
        std::vector<glm::vec4> f =
            renderFrames(single, scene, pathLighting(2, 1, 7, false), frame(16), 1).indirect;
        for (std::size_t p = 0; p < f.size(); ++p) sum[p] += f[p];
        if (i == 0) {
            ASSERT_NE(meanOf(f), 0.0);
        }
        if (i == 1) {
            ASSERT_NE(f, mean) << "single frames must differ from the accumulated mean";
        }
    }
    for (std::size_t p = 0; p < mean.size(); ++p) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(mean[p][c], sum[p][c] / kFrames, 1e-5f + 1e-5f * std::abs(mean[p][c]))
                << "pixel " << p;
        }
    }
}

// A moving camera drops the history: the frame after the move is exactly the frame a fresh
// renderer draws there with the same frame index.
TEST_F(PathIndirect, MovingCameraRestarts) {
    Scene scene = courtyard();
    const CameraPreset moved{"moved", {6.0f, 14.0f, 3.0f}, {23.0f, 3.0f, 22.0f}, 70.0f};
    const LightingSettings l = pathLighting(2, 1, 3);
    Renderer played(gpu_testing::context());
    renderFrames(played, scene, l, frame(16), 4);
    played.render(scene, moved, frame(16), l);
    const std::vector<glm::vec4> afterMove = played.readback().indirect;
    Renderer fresh(gpu_testing::context());
    fresh.setFrameIndex(4);
    fresh.render(scene, moved, frame(16), l);
    EXPECT_EQ(afterMove, fresh.readback().indirect);
}
