// ReSTIR's bias, seen and bounded: each ReSTIR mode after 16 and after 64 frames of a still camera
// against the path tracer's direct light, on the shipped lit worlds and on a room lit by many
// single-voxel ceiling lamps over boxes. Compared are means of non-emitter pixels (averaged over
// seeds; pixels within 2 voxels of an emitter left out, see measuredMask) and, for the default
// biased area mode, every 16x16 tile that carries light.
#include <cmath>
#include <functional>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "gpu/sample_stats.h"
#include "scene/scene_file.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace engine::scene;
using namespace gpu_testing;

namespace {

constexpr std::uint32_t kSize = 64;
constexpr std::uint32_t kTile = 16;
// Seeds per mode. The tiles next to a large emitter carry heavy-tailed noise (a surface beside
// an emitting face sees it at any distance down to zero), so the tile check averages more runs.
constexpr int kSeedsForMeans = 4;
constexpr int kSeedsForTiles = 16;
constexpr int kReferenceRuns = 16;  // of 1024 samples: thousands of small lights converge slowly

// A 96x40x96 room, ceiling at y = 36, with 12 x 12 = 144 single-voxel lamps of four colours set
// flush into the ceiling and boxes of several heights on the floor: many small lights, each
// hidden from most of the floor by some box.
Scene lampRoom() {
    Scene scene;
    scene.grid = BrickGrid({96, 40, 96});
    const MaterialId white = scene.palette.add(Material{"white", glm::vec3(0.75f)}).value();
    const MaterialId grey =
        scene.palette.add(Material{"grey", glm::vec3(0.5f, 0.45f, 0.4f)}).value();
    const glm::vec3 colours[4] = {
        {1.0f, 0.85f, 0.6f}, {0.5f, 0.7f, 1.0f}, {1.0f, 0.4f, 0.3f}, {0.5f, 1.0f, 0.5f}};
    MaterialId lamps[4];
    for (int i = 0; i < 4; ++i) {
        lamps[i] = scene.palette
                       .add(Material{"lamp" + std::to_string(i), glm::vec3(0.8f), colours[i], 8.0f})
                       .value();
    }
    fillBox(scene.grid, Box{{0, 0, 0}, {96, 2, 96}}, white);    // floor
    fillBox(scene.grid, Box{{0, 36, 0}, {96, 40, 96}}, white);  // ceiling
    fillBox(scene.grid, Box{{0, 2, 0}, {2, 36, 96}}, white);    // walls
    fillBox(scene.grid, Box{{94, 2, 0}, {96, 36, 96}}, white);
    fillBox(scene.grid, Box{{0, 2, 94}, {96, 36, 96}}, white);
    for (int i = 0; i < 12; ++i) {
        for (int k = 0; k < 12; ++k)
            scene.grid.set({6 + 7 * i, 36, 6 + 7 * k}, lamps[(i + 2 * k) % 4]);
    }
    const int boxes[][6] = {{10, 2, 14, 22, 14, 26}, {40, 2, 20, 48, 24, 28},
                            {64, 2, 12, 80, 8, 20},  {20, 2, 50, 30, 18, 66},
                            {52, 2, 56, 60, 30, 64}, {72, 2, 70, 86, 12, 84},
                            {34, 2, 76, 44, 6, 90}};
    for (const auto& b : boxes)
        fillBox(scene.grid, Box{{b[0], b[1], b[2]}, {b[3], b[4], b[5]}}, grey);
    scene.sky.sunRadiance = glm::vec3(0.0f);
    scene.sky.skyRadiance = glm::vec3(0.0f);
    scene.cameras.push_back(
        CameraPreset{"inside", {48.0f, 30.0f, 4.0f}, {48.0f, 4.0f, 60.0f}, 70.0f});
    scene.grid.clearDirty();
    return scene;
}

// Surface pixels that do not emit and are at least 3 voxels from any emitter: the light the
// estimators under test are responsible for, where their variance is finite. (A receiver touching
// an emitting face sees it at distances down to zero; area sampling's cos cos / d^2 then has
// unbounded variance, and the reference and ReSTIR alike show heavy-tailed noise there that many
// thousands of samples do not average out.)
std::vector<bool> measuredMask(const FrameImages& img, const Scene& scene) {
    std::vector<bool> mask(img.gbuffer.size());
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const shared::GBufferTexel& g = img.gbuffer[i];
        const std::uint32_t face = std::uint32_t(g.voxel.w);
        if (face >= 6 || scene.palette[MaterialId(g.data.x)].emissive()) continue;
        const glm::ivec3 front = glm::ivec3(g.voxel) + faceNormal(face);
        bool nearEmitter = false;
        for (int z = -2; z <= 2 && !nearEmitter; ++z) {
            for (int y = -2; y <= 2 && !nearEmitter; ++y) {
                for (int x = -2; x <= 2 && !nearEmitter; ++x) {
                    const glm::ivec3 v = front + glm::ivec3(x, y, z);
                    if (glm::any(glm::lessThan(v, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(v, scene.grid.sizeInVoxels())))
                        continue;
                    const MaterialId m = scene.grid.get(v);
                    nearEmitter = m != kEmpty && scene.palette[m].emissive();
                }
            }
        }
        mask[i] = !nearEmitter;
    }
    return mask;
}

double maskedMean(const std::vector<glm::vec4>& img, const std::vector<bool>& mask) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < img.size(); ++i) {
        if (!mask[i]) continue;
        sum += luminance(img[i]);
        ++n;
    }
    return n ? sum / n : 0.0;
}

struct ModeRun {
    MeanAndError at16, at64;
    std::vector<std::vector<glm::vec4>> images16, images64;  // one per seed
};

// `seeds` independent runs of 64 frames from an empty history; images after 16 and after 64.
ModeRun runMode(Renderer& r, Scene& scene, LightingSettings l, const std::vector<bool>& mask,
                int seeds) {
    ModeRun run;
    std::vector<double> means16, means64;
    for (int seed = 0; seed < seeds; ++seed) {
        l.seed = 7000 + std::uint32_t(seed);
        r.resetHistory();
        for (int f = 1; f <= 64; ++f) {
            r.render(scene, scene.camera(), frame(kSize), l);
            if (f != 16 && f != 64) continue;
            std::vector<glm::vec4> img = r.readback().radiance;
            (f == 16 ? means16 : means64).push_back(maskedMean(img, mask));
            (f == 16 ? run.images16 : run.images64).push_back(std::move(img));
        }
    }
    run.at16 = meanOfMeans(means16);
    run.at64 = meanOfMeans(means64);
    return run;
}

struct TileCheck {
    int tiles = 0;             // tiles whose reference mean exceeds 10 % of the image mean
    double worst = 0.0;        // the largest |mean over seeds / reference - 1| among them
    double worstSigma = 0.0;   // that tile's standard error over seeds, relative to the reference
    double worstExcess = 0.0;  // the largest (|error| - 10 %) / standard error: > 2 fails
};

// The 16x16 tiles that carry light, each tile's mean over seeds against the reference's.
TileCheck checkTiles(const std::vector<std::vector<glm::vec4>>& images,
                     const std::vector<glm::vec4>& ref, const std::vector<bool>& mask,
                     double imageMean) {
    TileCheck check;
    for (std::uint32_t ty = 0; ty < kSize; ty += kTile) {
        for (std::uint32_t tx = 0; tx < kSize; tx += kTile) {
            auto tileSum = [&](const std::vector<glm::vec4>& img, int& n) {
                double sum = 0.0;
                n = 0;
                for (std::uint32_t y = ty; y < ty + kTile; ++y) {
                    for (std::uint32_t x = tx; x < tx + kTile; ++x) {
                        std::size_t i = x + y * kSize;
                        if (!mask[i]) continue;
                        sum += luminance(img[i]);
                        ++n;
                    }
                }
                return sum;
            };
            int n = 0;
            const double reference = tileSum(ref, n);
            if (n < int(kTile * kTile / 4) || reference / n <= 0.1 * imageMean) continue;
            ++check.tiles;
            std::vector<double> ratios;
            for (const auto& img : images) ratios.push_back(tileSum(img, n) / reference);
            const MeanAndError s = meanOfMeans(ratios);
            if (std::abs(s.mean - 1.0) > check.worst) {
                check.worst = std::abs(s.mean - 1.0);
                check.worstSigma = s.standardError;
            }
            check.worstExcess =
                std::max(check.worstExcess, (std::abs(s.mean - 1.0) - 0.10) / s.standardError);
        }
    }
    return check;
}

struct BiasCase {
    const char* name;
    std::function<Scene()> make;
};

void PrintTo(const BiasCase& c, std::ostream* os) { *os << c.name; }

}  // namespace

class RestirBias : public GpuTest, public ::testing::WithParamInterface<BiasCase> {};

// Biased area (the default): mean within 3 % after 16 and 64 frames, and every lit tile within
// 10 % (averaged over 16 seeds, up to 2 standard errors of their spread). Unbiased area: mean
// within 4 standard errors (seeds' spread and the reference's). Point: mean within 10 % (its lights
// are points, the reference's are areas).
TEST_P(RestirBias, ModesAgreeWithThePathTracer) {
    Scene scene = GetParam().make();
    ASSERT_GT(scene.grid.sizeInVoxels().x, 0);
    Renderer r(gpu_testing::context());

    // The reference: independent 1024-sample runs; their spread gives its own error.
    LightingSettings ref;
    ref.method = Method::Reference;
    ref.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;  // the G-buffer's hits,
                                                                           // as ReSTIR shades them
    ref.samplesPerFrame = 32;
    std::vector<glm::vec4> reference(kSize * kSize, glm::vec4(0.0f));
    std::vector<double> refMeans;
    std::vector<bool> mask;
    for (int run = 0; run < kReferenceRuns; ++run) {
        ref.seed = 300 + std::uint32_t(run);
        r.resetHistory();
        for (int f = 0; f < 32; ++f) r.render(scene, scene.camera(), frame(kSize), ref);
        FrameImages img = r.readback();
        if (mask.empty()) mask = measuredMask(img, scene);
        refMeans.push_back(maskedMean(img.radiance, mask));
        for (std::size_t i = 0; i < reference.size(); ++i)
            reference[i] += img.radiance[i] / float(kReferenceRuns);
    }
    const MeanAndError refStats = meanOfMeans(refMeans);
    const double refMean = refStats.mean;
    const double refError = refStats.standardError;
    ASSERT_GT(refMean, 1e-3) << "the scene is lit";

    LightingSettings biased;
    LightingSettings unbiased;
    unbiased.restir.unbiased = true;
    LightingSettings point;
    point.area = false;
    const ModeRun b = runMode(r, scene, biased, mask, kSeedsForTiles);
    const ModeRun u = runMode(r, scene, unbiased, mask, kSeedsForMeans);
    const ModeRun p = runMode(r, scene, point, mask, kSeedsForMeans);

    const TileCheck tiles16 = checkTiles(b.images16, reference, mask, refMean);
    const TileCheck tiles64 = checkTiles(b.images64, reference, mask, refMean);
    std::printf(
        "%s: reference mean %.5f (+- %.5f); mean / reference after 16 and 64 frames:\n"
        "  biased area   %.4f %.4f (worst of %d lit 16x16 tiles off by %.1f %% +- %.1f and %.1f %% "
        "+- %.1f)\n"
        "  unbiased area %.4f %.4f (+- %.4f %.4f)\n"
        "  point         %.4f %.4f\n",
        GetParam().name, refMean, refError, b.at16.mean / refMean, b.at64.mean / refMean,
        tiles64.tiles, 100.0 * tiles16.worst, 100.0 * tiles16.worstSigma, 100.0 * tiles64.worst,
        100.0 * tiles64.worstSigma, u.at16.mean / refMean, u.at64.mean / refMean,
        u.at16.standardError / refMean, u.at64.standardError / refMean, p.at16.mean / refMean,
        p.at64.mean / refMean);

    EXPECT_NEAR(b.at16.mean / refMean, 1.0, 0.03) << "biased area, 16 frames";
    EXPECT_NEAR(b.at64.mean / refMean, 1.0, 0.03) << "biased area, 64 frames";
    // A tile's error is bias plus the seeds' noise; the many-light worlds' tiles keep a few per
    // cent of noise after 16 seeds (heavy-tailed: thousands of small lights), so a tile fails when
    // it is off by more than 10 % by more than 2 of its own standard errors.
    EXPECT_LE(tiles16.worstExcess, 2.0)
        << "biased area, 16 frames: a lit tile is off by more than 10 %";
    EXPECT_LE(tiles64.worstExcess, 2.0)
        << "biased area, 64 frames: a lit tile is off by more than 10 %";
    EXPECT_GT(tiles64.tiles, 0);
    for (const MeanAndError* s : {&u.at16, &u.at64}) {
        const double sigma = std::sqrt(s->standardError * s->standardError + refError * refError);
        EXPECT_LT(std::abs(s->mean - refMean), 4.0 * sigma + 1e-3 * refMean) << "unbiased area";
    }
    EXPECT_NEAR(p.at16.mean / refMean, 1.0, 0.10) << "point, 16 frames";
    EXPECT_NEAR(p.at64.mean / refMean, 1.0, 0.10) << "point, 64 frames";
}

INSTANTIATE_TEST_SUITE_P(
    Worlds, RestirBias,
    ::testing::Values(BiasCase{"cornell", [] { return loadWorld("cornell"); }},
                      BiasCase{"mountain", [] { return loadWorld("mountain"); }},
                      BiasCase{"letters", [] { return loadWorld("letters"); }},
                      BiasCase{"apartments", [] { return loadWorld("apartments"); }},
                      BiasCase{"lamp_room", lampRoom}),
    [](const ::testing::TestParamInfo<BiasCase>& p) { return std::string(p.param.name); });
