// The reference path tracer as a ground truth: its pixel filter against a supersampled CPU render
// of an edge-heavy scene, its MIS estimator against the older light-sampling-only estimator, and
// the GPU's voxel -> emitter derivation (used for MIS weights) against the CPU emitter list.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "gpu/sample_stats.h"
#include "lighting/emitter_list.h"
#include "render/camera.h"
#include "world/ray_traversal.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
using engine::lighting::ReferenceProbe;

namespace {

LightingSettings referenceSettings(std::uint32_t bounces, std::uint32_t seed, bool mis = true) {
    LightingSettings l;
    l.method = Method::Reference;
    l.samplesPerFrame = 16;
    l.bounces = bounces;
    l.seed = seed;
    l.referenceMis = mis;
    return l;
}

std::vector<glm::vec4> render(Scene& scene, const LightingSettings& l, std::uint32_t size,
                              std::uint32_t spp) {
    Renderer r(gpu_testing::context());
    return renderFrames(r, scene, l, frame(size), int(spp / l.samplesPerFrame)).radiance;
}

// Root-mean-square luminance difference per pixel, relative to the mean of `truth`.
double relativeRmse(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& truth) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += std::pow(luminance(a[i]) - luminance(truth[i]), 2.0);
    return std::sqrt(sum / double(a.size())) / meanLuminance(truth);
}

double maxAbsLuminanceError(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& truth) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(luminance(a[i]) - luminance(truth[i])));
    return worst;
}

// Many thin, high-contrast edges: one-voxel posts and beams that glow (seen directly) in front of
// the sky, over a black floor. Every surface is black (albedo 0), so each camera ray's radiance is
// exact — the sky, an emission or zero — and a pixel's only error is how it covers the edges.
Scene edgeScene() {
    Scene scene =
        paletteScene({64, 32, 64},
                     {Material{"black", glm::vec3(0.0f)},
                      Material{"warm", glm::vec3(0.0f), glm::vec3(1.0f, 0.8f, 0.5f), 4.0f},
                      Material{"cold", glm::vec3(0.0f), glm::vec3(0.4f, 0.7f, 1.0f), 2.5f}},
                     true);
    const MaterialId black = *scene.palette.find("black"), warm = *scene.palette.find("warm"),
                     cold = *scene.palette.find("cold");
    scene.sky.skyRadiance = glm::vec3(0.5f);
    fillBox(scene.grid, Box{{0, 0, 0}, {64, 2, 64}}, black);
    for (int i = 0; i < 14; ++i) {
        const int x = 4 + 4 * i, z = 20 + (i * 7) % 24, height = 6 + (i * 5) % 20;
        fillBox(scene.grid, Box{{x, 2, z}, {x + 1, 2 + height, z + 1}}, i % 2 ? warm : cold);
    }
    for (int j = 0; j < 5; ++j) {
        const int y = 8 + 4 * j, z = 46 + 3 * j;
        fillBox(scene.grid, Box{{2, y, z}, {62, y + 1, z + 1}}, j % 2 ? cold : warm);
    }
    scene.cameras.push_back(
        CameraPreset{"edges", {30.0f, 20.0f, -8.0f}, {34.0f, 12.0f, 40.0f}, 50.0f});
    scene.grid.clearDirty();
    return scene;
}

// The radiance a camera ray sees in edgeScene (mirrors skyBackground in common/surface.glsl).
glm::vec4 edgeSceneRadiance(const Scene& scene, const shared::FrameParams& f,
                            glm::vec2 imagePosition) {
    const glm::vec3 dir = engine::render::cameraRayDirectionAt(f, imagePosition);
    const RayHit h = traceRay(scene.grid, Ray{glm::vec3(f.cameraPosition), dir, 1.0e30f});
    if (h.hit) return glm::vec4(scene.palette[h.material].emittedRadiance(), 1.0f);
    const float up = std::clamp(dir.y * 0.5f + 0.5f, 0.0f, 1.0f);
    return glm::vec4(glm::vec3(f.skyRadiance) * (0.6f + (1.4f - 0.6f) * up), 1.0f);
}

}  // namespace

class Reference : public GpuTest {};

// A box-filtered pixel is the mean of the radiance over its square. Truth: a CPU render with
// 32 x 32 stratified rays per pixel (16 x 16 left a 2 % RMSE of its own). The reference (1024
// jittered samples) must match it in the whole-image mean (0.5 %) and per pixel (relative RMSE
// 3 %, the jitter's own noise being ~2 %; no pixel off by 0.4). The reference with one ray
// through each pixel centre — what it rendered from the G-buffer before, bit for bit — fails all
// three.
TEST_F(Reference, BoxFilteredPixelsMatchSupersampledEdges) {
    Scene scene = edgeScene();
    const std::uint32_t size = 64;
    const shared::FrameParams f =
        engine::render::makeFrameParams(scene.camera(), scene.sky, frame(size));
    std::vector<glm::vec4> supersampled(size * size);
    const int k = 32;
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) {
            glm::vec4 sum(0.0f);
            for (int a = 0; a < k; ++a)
                for (int b = 0; b < k; ++b) {
                    sum += edgeSceneRadiance(scene, f,
                                             glm::vec2(x, y) + (glm::vec2(a, b) + 0.5f) / float(k));
                }
            supersampled[x + y * size] = sum / float(k * k);
        }
    const std::vector<glm::vec4> filtered = render(scene, referenceSettings(0, 7), size, 1024);
    LightingSettings centre = referenceSettings(0, 7);
    centre.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
    const std::vector<glm::vec4> pixelCentre = render(scene, centre, size, 16);

    const double truthMean = meanLuminance(supersampled);
    const double filteredMeanError = std::abs(meanLuminance(filtered) - truthMean) / truthMean;
    const double centreMeanError = std::abs(meanLuminance(pixelCentre) - truthMean) / truthMean;
    const double filteredRmse = relativeRmse(filtered, supersampled),
                 centreRmse = relativeRmse(pixelCentre, supersampled);
    std::printf(
        "edge scene against %dx%d supersampling (mean luminance %.4f): box-filtered reference: "
        "mean error %.2f%%, "
        "relative RMSE %.3f, worst pixel %.3f; one ray through the pixel centre (the old "
        "reference): mean error "
        "%.2f%%, relative RMSE %.3f, worst pixel %.3f\n",
        k, k, truthMean, 100.0 * filteredMeanError, filteredRmse,
        maxAbsLuminanceError(filtered, supersampled), 100.0 * centreMeanError, centreRmse,
        maxAbsLuminanceError(pixelCentre, supersampled));
    EXPECT_LT(filteredMeanError, 0.005);
    EXPECT_LT(filteredRmse, 0.03);
    EXPECT_LT(maxAbsLuminanceError(filtered, supersampled),
              0.4);  // an eighth of the warm posts' luminance
    // The test tells the two apart: the pixel-centre image fails the same bounds.
    EXPECT_GT(centreMeanError, 0.005);
    EXPECT_GT(centreRmse, 0.03);
    EXPECT_GT(maxAbsLuminanceError(pixelCentre, supersampled), 0.4);

    // Seeded: the same settings give the same image, bit for bit.
    const std::vector<glm::vec4> again = render(scene, referenceSettings(0, 7), size, 16);
    const std::vector<glm::vec4> first = render(scene, referenceSettings(0, 7), size, 16);
    EXPECT_EQ(std::memcmp(again.data(), first.data(), again.size() * sizeof(glm::vec4)), 0);
}

namespace {

constexpr MaterialId kWhite = 1, kRed = 2, kLamp = 3, kBlue = 4;

// Lit by its emitters alone; brighter lamps than restir_test's, for fireflies.
Scene makeScene(glm::ivec3 size) {
    return paletteScene(
        size,
        {Material{"white", glm::vec3(0.75f)}, Material{"red", glm::vec3(0.7f, 0.1f, 0.1f)},
         Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 20.0f},
         Material{"blue", glm::vec3(0.8f), glm::vec3(0.3f, 0.5f, 1.0f), 12.0f}},
        true);
}

// A closed room split by a one-voxel wall with a doorway, small bright lamps against the walls
// and the ceiling: surfaces next to a lamp are where light sampling alone makes fireflies.
Scene thinWallRoom() {
    Scene scene = makeScene({40, 24, 40});
    fillBox(scene.grid, Box{{0, 0, 0}, {40, 1, 40}}, kWhite);    // floor
    fillBox(scene.grid, Box{{0, 23, 0}, {40, 24, 40}}, kWhite);  // ceiling
    fillBox(scene.grid, Box{{0, 0, 0}, {1, 24, 40}}, kRed);      // walls
    fillBox(scene.grid, Box{{39, 0, 0}, {40, 24, 40}}, kWhite);
    fillBox(scene.grid, Box{{0, 0, 39}, {40, 24, 40}}, kWhite);
    fillBox(scene.grid, Box{{0, 0, 0}, {40, 24, 1}}, kWhite);
    fillBox(scene.grid, Box{{20, 1, 1}, {21, 23, 39}}, kWhite);   // the thin wall
    fillBox(scene.grid, Box{{20, 1, 16}, {21, 12, 22}}, kEmpty);  // its doorway
    scene.grid.set({21, 18, 30}, kLamp);                          // against the thin wall
    scene.grid.set({30, 22, 10}, kLamp);                          // under the ceiling
    scene.grid.set({8, 1, 30}, kBlue);                            // on the floor behind the wall
    scene.grid.set({38, 6, 24}, kBlue);                           // against the side wall
    scene.cameras.push_back(
        CameraPreset{"inside", {34.0f, 14.0f, 3.0f}, {14.0f, 6.0f, 30.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

}  // namespace

// One bounce in a room of small bright lamps: MIS (light sampling weighted against cosine
// sampling) against light sampling alone. Both estimate the same image — the whole-image means
// over independent seeds agree within 4 standard errors — and MIS has the lower noise: the
// relative RMSE between two seeds' images and the mean per-pixel variance over the seeds.
TEST_F(Reference, MisMatchesLightSamplingWithLessNoise) {
    Scene scene = thinWallRoom();
    const std::uint32_t size = 64, spp = 64;
    const int seeds = 6;
    struct Figures {
        MeanAndError mean;
        double seedToSeedRmse = 0.0;  // RMSE between the images of seeds 0 and 1, per image, / mean
        double pixelVariance =
            0.0;  // per-pixel luminance variance over the seeds, averaged, / mean^2
    };
    // Pixels with a lamp in their 3 x 3 neighbourhood are left out of the noise figures: their
    // noise is the pixel filter's jitter across a lamp's edge, the same for both estimators.
    std::vector<bool> nearLamp(size * size, false);
    int litPixels = 0;
    {
        const FrameImages g = renderOnce(scene, scene.camera(), frame(size), kPreview);
        for (int y = 0; y < int(size); ++y)
            for (int x = 0; x < int(size); ++x) {
                const shared::GBufferTexel& t = g.gbuffer[std::size_t(x + y * int(size))];
                if (std::uint32_t(t.voxel.w) >= 6 ||
                    !scene.palette[MaterialId(t.data.x)].emissive())
                    continue;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx >= 0 && ny >= 0 && nx < int(size) && ny < int(size))
                            nearLamp[std::size_t(nx + ny * int(size))] = true;
                    }
            }
    }
    auto measure = [&](bool mis) {
        std::vector<std::vector<glm::vec4>> images;
        std::vector<double> means;
        for (int s = 0; s < seeds; ++s) {
            images.push_back(
                render(scene, referenceSettings(1, 300 + std::uint32_t(s), mis), size, spp));
            means.push_back(meanLuminance(images.back()));
        }
        Figures fig;
        fig.mean = meanOfMeans(means);
        double variance = 0.0, difference = 0.0;
        int counted = 0;
        for (std::size_t i = 0; i < images[0].size(); ++i) {
            if (nearLamp[i]) continue;
            double m = 0.0, v = 0.0;
            for (const auto& img : images) m += luminance(img[i]) / seeds;
            for (const auto& img : images) v += std::pow(luminance(img[i]) - m, 2.0) / (seeds - 1);
            variance += v;
            difference += std::pow(luminance(images[0][i]) - luminance(images[1][i]), 2.0);
            ++counted;
        }
        // Per image: the difference of two independent images has twice the variance.
        fig.seedToSeedRmse = std::sqrt(difference / counted / 2.0) / fig.mean.mean;
        fig.pixelVariance = variance / counted / (fig.mean.mean * fig.mean.mean);
        litPixels = counted;
        return fig;
    };
    const Figures old = measure(false), mis = measure(true);
    const double sigma = std::hypot(old.mean.standardError, mis.mean.standardError);
    std::printf(
        "thin-wall room, 1 bounce, %u spp x %d seeds, noise over the %d pixels not next to a lamp: "
        "light sampling only: mean %.5f +- %.5f, relative RMSE "
        "seed to seed %.3f, relative per-pixel variance %.4f; MIS: mean %.5f +- %.5f, relative "
        "RMSE %.3f, "
        "relative per-pixel variance %.4f; means differ by %.2f sigma, variance ratio %.4f\n",
        spp, seeds, litPixels, old.mean.mean, old.mean.standardError, old.seedToSeedRmse,
        old.pixelVariance, mis.mean.mean, mis.mean.standardError, mis.seedToSeedRmse,
        mis.pixelVariance, std::abs(old.mean.mean - mis.mean.mean) / sigma,
        mis.pixelVariance / old.pixelVariance);
    ASSERT_GT(mis.mean.mean, 0.01);
    EXPECT_LT(std::abs(old.mean.mean - mis.mean.mean), 4.0 * sigma);
    EXPECT_LT(mis.pixelVariance, 0.8 * old.pixelVariance);
    EXPECT_LT(mis.seedToSeedRmse, old.seedToSeedRmse);
}

// For MIS the GPU works out, from the grid, which light of the CPU emitter list a voxel hit by a
// bounce ray belongs to (there is no voxel -> slot map). Through every pixel that sees an emitter,
// its shape (corner, size, exposed faces) and power must be the CPU list's, with brick lights on
// and off: a brick light with a covered side, one touching the world's edge, voxel lights in a
// mixed brick.
TEST_F(Reference, GpuEmitterLookupMatchesCpuEmitterList) {
    Scene scene = makeScene({48, 32, 48});
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 8, 48}}, kWhite);
    fillBox(scene.grid, Box{{8, 8, 8}, {16, 16, 16}},
            kLamp);  // brick light on the floor: bottom covered
    fillBox(scene.grid, Box{{16, 8, 8}, {24, 12, 16}}, kWhite);  // half of its +x side covered
    fillBox(scene.grid, Box{{40, 8, 24}, {48, 16, 32}},
            kBlue);  // a brick light at the world's edge
    fillBox(scene.grid, Box{{26, 8, 30}, {30, 11, 33}}, kLamp);  // voxel lights in mixed bricks
    scene.grid.set({33, 9, 20}, kBlue);
    scene.grid.set({34, 8, 20}, kLamp);
    scene.cameras.push_back(
        CameraPreset{"over", {24.0f, 36.0f, -12.0f}, {26.0f, 8.0f, 22.0f}, 60.0f});
    scene.grid.clearDirty();
    const std::uint32_t size = 96;
    for (bool brickLights : {true, false}) {
        engine::lighting::EmitterList cpu({brickLights});
        cpu.rebuild(scene);
        (void)cpu.aliasTable();  // settles the total power as the GPU sees it
        const double totalPower = cpu.info().power.x;
        LightingSettings l = referenceSettings(0, 1);
        l.brickLights = brickLights;
        l.samplesPerFrame = 1;
        Renderer r(gpu_testing::context());
        l.referenceProbe = ReferenceProbe::EmitterShape;
        r.render(scene, scene.camera(), frame(size), l);
        const FrameImages shapes = r.readback();
        l.referenceProbe = ReferenceProbe::EmitterPower;
        r.render(scene, scene.camera(), frame(size), l);
        const FrameImages powers = r.readback();
        int checked = 0, bricks = 0, wrong = 0, nonEmittersWrong = 0;
        for (std::size_t i = 0; i < shapes.gbuffer.size(); ++i) {
            const shared::GBufferTexel& g = shapes.gbuffer[i];
            const glm::ivec3 v(g.voxel);
            const shared::GpuEmitter* match = nullptr;
            if (std::uint32_t(g.voxel.w) < 6) {
                for (std::uint32_t slot : cpu.aliveSlots()) {
                    const shared::GpuEmitter& e = cpu.slots()[slot];
                    glm::ivec3 lo(e.minCorner);
                    if (glm::all(glm::greaterThanEqual(v, lo)) &&
                        glm::all(glm::lessThan(v, lo + e.minCorner.w)))
                        match = &e;
                }
            }
            if (!match) {
                nonEmittersWrong += shapes.radiance[i] != glm::vec4(-1.0f);
                continue;
            }
            ++checked;
            bricks += match->minCorner.w == 8;
            const glm::vec4 expectedShape(
                glm::vec3(glm::ivec3(match->minCorner)),
                float(match->info.x | (std::uint32_t(match->minCorner.w) << 6)));
            const float power = match->radiance.w;
            const bool powerAgrees = std::abs(powers.radiance[i].x - power) <= 1e-5f * power &&
                                     std::abs(powers.radiance[i].y - float(power / totalPower)) <=
                                         1e-5f * float(power / totalPower);
            wrong += shapes.radiance[i] != expectedShape || !powerAgrees;
        }
        std::printf(
            "brick lights %s: %zu CPU emitters, %d pixels on emitters (%d on brick lights), %d "
            "disagree; %d "
            "other pixels claim an emitter\n",
            brickLights ? "on" : "off", cpu.aliveSlots().size(), checked, bricks, wrong,
            nonEmittersWrong);
        EXPECT_GT(checked, 300);
        if (brickLights) {
            EXPECT_GT(bricks, 100);
        }
        EXPECT_EQ(wrong, 0);
        EXPECT_EQ(nonEmittersWrong, 0);
    }
}

// Moving the sun (the HUD's sun controls) restarts every estimator that accumulates over still
// frames: after the sun and sky are switched off, one frame of a world lit only by them is black.
// Before, the sum kept the frames lit by the old sun and the image stayed lit.
TEST_F(Reference, ASkyChangeRestartsTheAccumulation) {
    Scene scene = paletteScene({32, 16, 32}, {Material{"grey", glm::vec3(0.6f)}}, false);
    fillBox(scene.grid, Box{{0, 0, 0}, {32, 2, 32}}, *scene.palette.find("grey"));
    fillBox(scene.grid, Box{{12, 2, 12}, {20, 10, 20}}, *scene.palette.find("grey"));
    scene.cameras.push_back(
        CameraPreset{"above", {16.0f, 24.0f, -6.0f}, {16.0f, 4.0f, 16.0f}, 60.0f});
    scene.grid.clearDirty();
    LightingSettings l = referenceSettings(1, 3);
    l.samplesPerFrame = 4;
    Renderer r(gpu_testing::context());
    const FrameImages lit = renderFrames(r, scene, l, frame(32), 3);
    ASSERT_GT(meanLuminance(lit.radiance), 0.05);
    scene.sky.sunRadiance = glm::vec3(0.0f);
    scene.sky.skyRadiance = glm::vec3(0.0f);
    const FrameImages dark = renderFrames(r, scene, l, frame(32), 1);
    EXPECT_EQ(meanLuminance(dark.radiance), 0.0);
}
