// Voxel ReSTIR against the reference path tracer and against analytic light, on small scenes.
#include <cmath>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "gpu/sample_stats.h"
#include "lighting/emitter_list.h"
#include "world/ray_traversal.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;

namespace {

constexpr MaterialId kWhite = 1, kRed = 2, kLamp = 3, kBlue = 4;

// Lit by its emitters alone.
Scene makeScene(glm::ivec3 size) {
    return paletteScene(
        size,
        {Material{"white", glm::vec3(0.75f)}, Material{"red", glm::vec3(0.7f, 0.1f, 0.1f)},
         Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 6.0f},
         Material{"blue", glm::vec3(0.8f), glm::vec3(0.3f, 0.5f, 1.0f), 3.0f}},
        true);
}

// A floor, a back wall, a pillar casting shadows, one 8^3 brick light and three voxel lights.
Scene roomScene() {
    Scene scene = makeScene({64, 40, 64});
    fillBox(scene.grid, Box{{0, 0, 0}, {64, 4, 64}}, kWhite);
    fillBox(scene.grid, Box{{0, 4, 56}, {64, 40, 64}}, kRed);
    fillBox(scene.grid, Box{{20, 4, 24}, {28, 22, 32}}, kWhite);
    fillBox(scene.grid, Box{{32, 24, 32}, {40, 32, 40}}, kLamp);  // a brick-aligned brick light
    scene.grid.set({10, 6, 12}, kBlue);
    scene.grid.set({50, 5, 20}, kLamp);
    scene.grid.set({45, 12, 50}, kBlue);
    scene.cameras.push_back(
        CameraPreset{"front", {32.0f, 36.0f, -22.0f}, {32.0f, 6.0f, 30.0f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

// Point mode with one candidate and no reuse: with a single emitter the sample is deterministic
// and W = 1, so the image is exactly the point light's (one shadow ray per pixel).
FrameImages renderOnePointLightSample(Scene& scene) {
    LightingSettings l;
    l.method = Method::Ris;
    l.area = false;
    l.restir.candidates = 1;
    l.restir.temporal = l.restir.spatial = l.restir.candidateVisibility = false;
    return renderOnce(scene, scene.camera(), frame(64), l);
}

std::vector<glm::vec4> reference(Scene& scene, std::uint32_t size, std::uint32_t spp,
                                 bool brickLights = true, std::uint32_t seed = 1) {
    Renderer r(gpu_testing::context());
    LightingSettings l;
    l.method = Method::Reference;
    l.referenceFilter =
        engine::lighting::ReferenceFilter::PixelCentre;  // ReSTIR and the quadrature are at pixel
                                                         // centres
    l.samplesPerFrame = 16;
    l.brickLights = brickLights;
    l.seed = seed;
    return renderFrames(r, scene, l, frame(size), int(spp / 16)).radiance;
}

}  // namespace

class Restir : public GpuTest {};

// The unbiased mode's mean over independent seeds converges to the direct-light reference: the
// per-image mean lies within 3 standard errors, and the error of the mean image falls like
// 1/sqrt(N).
TEST_F(Restir, UnbiasedModeConvergesToReference) {
    Scene scene = roomScene();
    const std::uint32_t size = 40;
    // The reference in 8 independent runs of 512 samples: their spread gives its own error.
    std::vector<glm::vec4> ref(size * size);
    std::vector<double> refMeans;
    for (std::uint32_t run = 0; run < 8; ++run) {
        std::vector<glm::vec4> img = reference(scene, size, 512, true, 500 + run);
        refMeans.push_back(meanLuminance(img));
        for (std::size_t i = 0; i < img.size(); ++i) ref[i] += img[i] / 8.0f;
    }
    const MeanAndError refStats = meanOfMeans(refMeans);
    const double refMean = refStats.mean;
    ASSERT_GT(refMean, 0.01);

    LightingSettings l;
    l.restir.unbiased = true;
    const int seeds = 32;
    std::vector<double> means;
    std::vector<glm::vec4> sumFew(ref.size()), sumAll(ref.size());
    Renderer r(gpu_testing::context());
    for (int s = 0; s < seeds; ++s) {
        l.seed = 1000 + std::uint32_t(s);
        r.resetHistory();
        std::vector<glm::vec4> img = renderFrames(r, scene, l, frame(size), 4).radiance;
        means.push_back(meanLuminance(img));
        for (std::size_t i = 0; i < img.size(); ++i) {
            if (s < seeds / 4) sumFew[i] += img[i];
            sumAll[i] += img[i];
        }
    }
    const MeanAndError restirStats = meanOfMeans(means);
    const double mean = restirStats.mean;
    const double sigma = std::sqrt(restirStats.standardError * restirStats.standardError +
                                   refStats.standardError * refStats.standardError);
    for (auto& p : sumFew) p /= float(seeds / 4);
    for (auto& p : sumAll) p /= float(seeds);
    double maeFew = mae(sumFew, ref), maeAll = mae(sumAll, ref);
    std::printf(
        "reference mean %.5f +- %.5f, unbiased ReSTIR mean %.5f +- %.5f: difference %.5f = %.2f "
        "sigma; MAE of "
        "the mean of %d seeds %.5f, of %d seeds %.5f (ratio %.2f, 1/sqrt(N) predicts 2.0)\n",
        refMean, refStats.standardError, mean, restirStats.standardError, mean - refMean,
        std::abs(mean - refMean) / sigma, seeds / 4, maeFew, seeds, maeAll, maeFew / maeAll);
    EXPECT_LT(std::abs(mean - refMean), 3.0 * sigma);
    EXPECT_GT(maeFew / maeAll, 1.5) << "the error of the mean should fall roughly as 1/sqrt(N)";
}

// A floor under a grid of one-voxel bars, lit by lamps above the bars: every few voxels of floor
// see a different set of lamps, so a pixel and the surface it reprojects to last frame disagree
// about visibility wherever the camera moves. The camera below the bars slides sideways by a
// fraction of a pixel per frame.
Scene barredRoom() {
    Scene scene = makeScene({48, 32, 48});
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 2, 48}}, kWhite);
    for (int x = 2; x < 48; x += 3) fillBox(scene.grid, Box{{x, 8, 0}, {x + 1, 9, 48}}, kWhite);
    for (int z = 2; z < 48; z += 4) fillBox(scene.grid, Box{{0, 9, z}, {48, 10, z + 1}}, kWhite);
    const glm::ivec3 lamps[] = {
        {8, 20, 10}, {30, 21, 14}, {20, 19, 30}, {40, 20, 38}, {12, 22, 40}};
    for (int i = 0; i < 5; ++i)
        fillBox(scene.grid, Box{lamps[i], lamps[i] + glm::ivec3(3, 1, 3)}, i % 2 ? kBlue : kLamp);
    scene.cameras.push_back(
        CameraPreset{"below", {10.0f, 6.0f, 1.0f}, {26.0f, 2.0f, 30.0f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

CameraPreset slidingCamera(const Scene& scene, int frameIndex) {
    CameraPreset c = scene.cameras.front();
    const glm::vec3 step{0.23f, 0.0f, 0.11f};
    c.position += step * float(frameIndex);
    c.target += step * float(frameIndex);
    return c;
}

// The unbiased mode (pairwise MIS in spatial reuse, the balance heuristic with last frame's
// visibility in temporal reuse) on a moving camera over bar shadows: the mean of the last frame
// over independent seeds lies within 4 standard errors of the reference's for that view. The
// default mode, which counts last frame's reservoir as if its surface were this one's, is printed
// beside it.
TEST_F(Restir, UnbiasedModeConvergesOnAMovingCamera) {
    Scene scene = barredRoom();
    const std::uint32_t size = 48;
    const int frames = 12;
    const CameraPreset last = slidingCamera(scene, frames - 1);
    Renderer r(gpu_testing::context());

    LightingSettings ref;
    ref.method = Method::Reference;
    ref.referenceFilter = engine::lighting::ReferenceFilter::PixelCentre;
    ref.samplesPerFrame = 32;
    std::vector<double> refMeans;
    for (std::uint32_t run = 0; run < 4; ++run) {
        ref.seed = 900 + run;
        r.resetHistory();
        for (int f = 0; f < 8; ++f) r.render(scene, last, frame(size), ref);
        refMeans.push_back(meanLuminance(r.readback().radiance));
    }
    const MeanAndError refStats = meanOfMeans(refMeans);
    ASSERT_GT(refStats.mean, 0.005);

    auto lastFrameMeans = [&](LightingSettings l, int seeds) {
        std::vector<double> means;
        for (int s = 0; s < seeds; ++s) {
            l.seed = 2000 + std::uint32_t(s);
            r.resetHistory();
            for (int f = 0; f < frames; ++f)
                r.render(scene, slidingCamera(scene, f), frame(size), l);
            means.push_back(meanLuminance(r.readback().radiance));
        }
        return meanOfMeans(means);
    };
    LightingSettings unbiased;
    unbiased.restir.unbiased = true;
    const MeanAndError u = lastFrameMeans(unbiased, 16);
    const MeanAndError b = lastFrameMeans(LightingSettings{}, 8);
    const double sigma = std::sqrt(u.standardError * u.standardError +
                                   refStats.standardError * refStats.standardError);
    std::printf(
        "moving camera: reference mean %.5f +- %.5f; unbiased %.5f +- %.5f (%.4f of the reference, "
        "%.2f "
        "sigma); default mode %.5f +- %.5f (%.4f)\n",
        refStats.mean, refStats.standardError, u.mean, u.standardError, u.mean / refStats.mean,
        std::abs(u.mean - refStats.mean) / sigma, b.mean, b.standardError, b.mean / refStats.mean);
    EXPECT_LT(std::abs(u.mean - refStats.mean), 4.0 * sigma);
}

// Point mode with one free-standing voxel light equals an analytic point light at its centre,
// pixel for pixel (one emitter, one candidate: the sample is deterministic and W = 1).
TEST_F(Restir, PointModeMatchesAnalyticPointLight) {
    Scene scene = makeScene({48, 32, 48});
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 2, 48}}, kWhite);
    fillBox(scene.grid, Box{{14, 2, 20}, {22, 9, 24}}, kRed);  // a blocker casting a hard shadow
    const glm::ivec3 lamp{20, 12, 28};
    scene.grid.set(lamp, kLamp);
    scene.cameras.push_back(
        CameraPreset{"top", {24.0f, 40.0f, -6.0f}, {24.0f, 2.0f, 26.0f}, 60.0f});
    scene.grid.clearDirty();
    FrameImages img = renderOnePointLightSample(scene);

    const glm::vec3 centre = glm::vec3(lamp) + 0.5f;
    const glm::vec3 le = scene.palette[kLamp].emittedRadiance();
    int checked = 0, bad = 0, shadowed = 0;
    for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
        const shared::GBufferTexel& g = img.gbuffer[i];
        std::uint32_t face = std::uint32_t(g.voxel.w);
        if (face >= 6) continue;
        glm::vec3 n(faceNormal(face));
        glm::vec3 p(g.position);
        glm::vec3 albedo = scene.palette[MaterialId(g.data.x)].albedo;
        glm::vec3 d = centre - p;
        float dist = glm::length(d);
        glm::vec3 w = d / dist;
        glm::vec3 expected = scene.palette[MaterialId(g.data.x)].emittedRadiance();
        float cosX = glm::dot(n, w);
        if (cosX > 0.0f && glm::ivec3(g.voxel) != lamp) {
            // Intensity towards p: radiance x projected area of the cube's exposed faces.
            float projected = std::abs(w.x) + std::abs(w.y) + std::abs(w.z);
            // The shadow ray aims at the centre of the face turned most towards p.
            glm::vec3 target = centre;
            float best = 0.0f;
            for (std::uint32_t f = 0; f < 6; ++f) {
                glm::vec3 c = centre + 0.5f * glm::vec3(faceNormal(f));
                float cosine = glm::dot(glm::vec3(faceNormal(f)), glm::normalize(p - c));
                if (cosine > best) best = cosine, target = c;
            }
            float shadowDist = glm::length(target - p);
            RayHit h = traceRay(scene.grid,
                                Ray{p + n * 1e-3f, (target - p) / shadowDist, shadowDist + 1e-3f});
            bool visible = !h.hit || h.voxel == lamp;
            shadowed += !visible;
            if (visible) expected += albedo / float(M_PI) * le * projected * cosX / (dist * dist);
        }
        glm::vec3 got(img.radiance[i]);
        ++checked;
        float err = glm::length(got - expected) / std::max(glm::length(expected), 1e-3f);
        bad += err > 1e-3f;
    }
    std::printf("point light: %d lit pixels checked, %d in shadow, %d differ by more than 0.1%%\n",
                checked, shadowed, bad);
    EXPECT_GT(checked, 2000);
    EXPECT_GT(shadowed, 20);
    EXPECT_LE(bad, checked / 500) << "only grazing shadow-boundary pixels may differ";
}

// Point mode beside a lamp set flush into the ceiling: the walls of the room are lit as the area
// light lights them, also where they see the lamp from more than 45 degrees off its face (where a
// shadow ray aimed at the emitter's centre crosses the ceiling voxel next to it and finds it dark).
TEST_F(Restir, PointModeLightsWallsBesideAFlushLamp) {
    Scene scene = makeScene({32, 24, 32});
    fillBox(scene.grid, Box{{0, 0, 0}, {32, 2, 32}}, kWhite);    // floor
    fillBox(scene.grid, Box{{0, 20, 0}, {32, 24, 32}}, kWhite);  // ceiling
    fillBox(scene.grid, Box{{0, 2, 0}, {2, 20, 32}}, kRed);      // walls
    fillBox(scene.grid, Box{{30, 2, 0}, {32, 20, 32}}, kRed);
    fillBox(scene.grid, Box{{0, 2, 30}, {32, 20, 32}}, kWhite);
    const glm::ivec3 lamp{16, 20, 16};
    scene.grid.set(lamp, kLamp);  // only its lower face is exposed
    scene.cameras.push_back(
        CameraPreset{"inside", {16.0f, 11.0f, 1.5f}, {16.0f, 11.0f, 30.0f}, 90.0f});
    scene.grid.clearDirty();
    FrameImages img = renderOnePointLightSample(scene);

    // The area light by quadrature of its lower face (no occluder but the room itself, which the
    // lower face's cosine already excludes): the light each wall pixel should get.
    const glm::vec3 le = scene.palette[kLamp].emittedRadiance();
    int walls = 0, steep = 0, dark = 0, off = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
        const shared::GBufferTexel& g = img.gbuffer[i];
        std::uint32_t face = std::uint32_t(g.voxel.w);
        if (face >= 6 || (face >> 1) == 1u) continue;  // walls only (not floor or ceiling)
        glm::vec3 n(faceNormal(face));
        glm::vec3 p(g.position);
        glm::vec3 albedo = scene.palette[MaterialId(g.data.x)].albedo;
        glm::vec3 quad(0.0f);
        const int k = 16;
        for (int a = 0; a < k; ++a) {
            for (int b = 0; b < k; ++b) {
                glm::vec3 y(lamp.x + (a + 0.5f) / k, float(lamp.y), lamp.z + (b + 0.5f) / k);
                glm::vec3 d = y - p;
                float dist = glm::length(d);
                glm::vec3 w = d / dist;
                float cx = glm::dot(n, w), cy = w.y;  // the lamp's lit face looks down
                if (cx > 0.0f && cy > 0.0f)
                    quad += albedo / float(M_PI) * le * cx * cy / (dist * dist) / float(k * k);
            }
        }
        if (glm::length(quad) < 1e-4f) continue;
        ++walls;
        glm::vec3 toLamp = glm::vec3(lamp) + glm::vec3(0.5f, 0.0f, 0.5f) - p;
        steep += -glm::normalize(toLamp).y < std::cos(float(M_PI) / 4.0f);
        glm::vec3 got = glm::vec3(img.radiance[i]);
        dark += glm::length(got) == 0.0f;
        double err = glm::length(got - quad) / glm::length(quad);
        worst = std::max(worst, err);
        off += err > 0.05;
    }
    std::printf(
        "point mode beside a flush lamp: %d lit wall pixels (%d seeing the lamp more than 45 "
        "degrees off its "
        "face), %d dark, %d off the area light by more than 5 %%, worst %.1f %%\n",
        walls, steep, dark, off, 100.0 * worst);
    EXPECT_GT(steep, 500);
    EXPECT_EQ(dark, 0);
    EXPECT_EQ(off, 0);
}

// A brick light and its 8^3 voxels as separate emitters light the scene identically.
TEST_F(Restir, BrickLightsAndVoxelEmittersConvergeToTheSameImage) {
    Scene scene = roomScene();
    const std::uint32_t size = 32;
    std::vector<glm::vec4> bricks = reference(scene, size, 2048, true);
    std::vector<glm::vec4> voxels = reference(scene, size, 2048, false);
    double a = meanLuminance(bricks), b = meanLuminance(voxels);
    double err = mae(bricks, voxels);
    std::printf("brick lights: mean %.5f, voxel emitters: mean %.5f, MAE between them %.5f\n", a, b,
                err);
    EXPECT_NEAR(a, b, 0.01 * a);
    EXPECT_LT(err, 0.05 * a);
}

// Removing a light: no pixel is lit by it in the very next frame. Adding one: it shows up within
// a few frames.
TEST_F(Restir, EditedEmittersTakeEffectImmediately) {
    // Two rooms split by a wall up to the top of the world; the camera looks down into both.
    Scene scene = makeScene({64, 32, 32});
    fillBox(scene.grid, Box{{0, 0, 0}, {64, 2, 32}}, kWhite);
    fillBox(scene.grid, Box{{31, 2, 0}, {33, 32, 32}}, kWhite);
    const glm::ivec3 lampA{12, 4, 16}, lampB{50, 4, 16};
    scene.grid.set(lampA, kLamp);
    scene.grid.set(lampB, kBlue);
    scene.cameras.push_back(
        CameraPreset{"above", {32.0f, 70.0f, 16.0f}, {32.0f, 0.0f, 16.01f}, 50.0f});
    scene.grid.clearDirty();
    Renderer r(gpu_testing::context());
    LightingSettings l;  // biased ReSTIR with temporal and spatial reuse
    auto roomA = [&](const FrameImages& img, double& mean, float& maxValue) {
        double sum = 0.0;
        int n = 0;
        maxValue = 0.0f;
        for (std::size_t i = 0; i < img.gbuffer.size(); ++i) {
            const auto& g = img.gbuffer[i];
            if (std::uint32_t(g.voxel.w) != shared::FACE_POS_Y || g.voxel.y != 1 || g.voxel.x >= 31)
                continue;
            sum += img.radiance[i].x + img.radiance[i].y + img.radiance[i].z;
            maxValue =
                std::max(maxValue, img.radiance[i].x + img.radiance[i].y + img.radiance[i].z);
            ++n;
        }
        mean = sum / std::max(n, 1);
    };
    double mean;
    float maxValue;
    for (int i = 0; i < 6; ++i) r.render(scene, scene.camera(), frame(48), l);
    roomA(r.readback(), mean, maxValue);
    ASSERT_GT(mean, 1e-3) << "room A is lit by its lamp";

    scene.grid.set(lampA, kEmpty);
    r.render(scene, scene.camera(), frame(48), l);
    roomA(r.readback(), mean, maxValue);
    EXPECT_EQ(maxValue, 0.0f) << "a pixel was lit by a removed emitter";

    // Put a lamp back elsewhere in room A and count frames until room A is near steady state.
    scene.grid.set({20, 6, 10}, kLamp);
    std::vector<double> means;
    for (int i = 0; i < 12; ++i) {
        r.render(scene, scene.camera(), frame(48), l);
        roomA(r.readback(), mean, maxValue);
        means.push_back(mean);
    }
    double steady = (means[9] + means[10] + means[11]) / 3.0;
    int frames = 0;
    while (frames < 12 && means[frames] < 0.8 * steady) ++frames;
    std::printf("an added lamp reached 80%% of its steady brightness after %d frame(s)\n",
                frames + 1);
    EXPECT_LE(frames + 1, 5)
        << "temporal history (M capped at 20x) may delay a new light by a few frames, no more";
}

// Switching a light off: the lights that remain are not brightened while history decays. (Last
// frame's reservoirs that held the removed light were dropped, so only those that happened to
// hold a surviving light were reused, their weights still counting the removed one.)
TEST_F(Restir, SwitchingALightOffDoesNotBrightenTheOthers) {
    Scene scene = roomScene();
    const std::uint32_t size = 40;
    const Box brickLight{{32, 24, 32}, {40, 32, 40}};
    Scene edited = roomScene();
    fillBox(edited.grid, brickLight, kEmpty);
    edited.grid.clearDirty();
    std::vector<glm::vec4> ref = reference(edited, size, 2048);
    const double refMean = meanLuminance(ref);
    for (bool unbiased : {false, true}) {
        LightingSettings l;
        l.restir.unbiased = unbiased;
        std::vector<double> after1, after4;
        for (std::uint32_t seed = 0; seed < 6; ++seed) {
            Scene s = roomScene();
            l.seed = 40 + seed;
            Renderer r(gpu_testing::context());
            renderFrames(r, s, l, frame(size), 20);
            fillBox(s.grid, brickLight, kEmpty);
            after1.push_back(meanLuminance(renderFrames(r, s, l, frame(size), 1).radiance));
            after4.push_back(meanLuminance(renderFrames(r, s, l, frame(size), 3).radiance));
        }
        const MeanAndError a1 = meanOfMeans(after1), a4 = meanOfMeans(after4);
        std::printf(
            "%s: after the brick light went off, mean / converged mean 1 frame later %.3f (+- "
            "%.3f), 4 frames "
            "later %.3f (+- %.3f)\n",
            unbiased ? "unbiased" : "biased", a1.mean / refMean, a1.standardError / refMean,
            a4.mean / refMean, a4.standardError / refMean);
        EXPECT_NEAR(a1.mean / refMean, 1.0, 0.05 + 3.0 * a1.standardError / refMean);
        EXPECT_NEAR(a4.mean / refMean, 1.0, 0.05 + 3.0 * a4.standardError / refMean);
    }
}

// The reference path tracer's direct light against an independent CPU quadrature of the area
// light integral (each exposed emitter face cut into 24 x 24 patches, CPU shadow rays), at
// sampled pixels: agreement within 4 standard errors of the reference's own noise.
TEST_F(Restir, ReferenceDirectLightMatchesQuadrature) {
    Scene scene = makeScene({48, 32, 48});
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 2, 48}}, kWhite);
    fillBox(scene.grid, Box{{12, 2, 22}, {30, 10, 24}}, kRed);    // a wall casting a soft shadow
    fillBox(scene.grid, Box{{16, 16, 24}, {24, 24, 32}}, kLamp);  // brick light
    scene.grid.set({34, 5, 12}, kBlue);                           // voxel light
    scene.cameras.push_back(
        CameraPreset{"top", {24.0f, 44.0f, -10.0f}, {24.0f, 2.0f, 24.0f}, 55.0f});
    scene.grid.clearDirty();
    const std::uint32_t size = 32;
    const int runs = 8;
    std::vector<std::vector<glm::vec4>> images;
    for (int run = 0; run < runs; ++run)
        images.push_back(reference(scene, size, 512, true, 900 + std::uint32_t(run)));
    FrameImages g = renderOnce(scene, scene.camera(), frame(size), kPreview);

    engine::lighting::EmitterList lights;
    lights.rebuild(scene);
    int checked = 0, outliers = 0;
    double worst = 0.0;
    for (std::uint32_t i = 0; i < size * size; i += 7) {
        const shared::GBufferTexel& t = g.gbuffer[i];
        if (std::uint32_t(t.voxel.w) >= 6 || t.data.x == kLamp || t.data.x == kBlue) continue;
        glm::vec3 n(faceNormal(std::uint32_t(t.voxel.w)));
        glm::vec3 x(t.position);
        glm::vec3 albedo = scene.palette[MaterialId(t.data.x)].albedo;
        glm::vec3 quad(0.0f);
        for (std::uint32_t slot : lights.aliveSlots()) {
            const shared::GpuEmitter& e = lights.slots()[slot];
            float side = float(e.minCorner.w);
            for (std::uint32_t f = 0; f < 6; ++f) {
                if (!(e.info.x & (1u << f))) continue;
                int axis = int(f >> 1), ua = (axis + 1) % 3, va = (axis + 2) % 3;
                glm::vec3 nf(faceNormal(f));
                const int k = 24;
                float dA = (side / k) * (side / k);
                for (int a = 0; a < k; ++a)
                    for (int b = 0; b < k; ++b) {
                        glm::vec3 y = glm::vec3(glm::ivec3(e.minCorner));
                        y[axis] += (f & 1) ? side : 0.0f;
                        y[ua] += (a + 0.5f) * side / k;
                        y[va] += (b + 0.5f) * side / k;
                        glm::vec3 d = y - x;
                        float dist = glm::length(d);
                        glm::vec3 w = d / dist;
                        float cx = glm::dot(n, w), cy = glm::dot(nf, -w);
                        if (cx <= 0.0f || cy <= 0.0f) continue;
                        RayHit h = traceRay(scene.grid, Ray{x + n * 1e-3f, w, dist + 1e-3f});
                        glm::ivec3 lo(e.minCorner);
                        bool visible =
                            !h.hit || (glm::all(glm::greaterThanEqual(h.voxel, lo)) &&
                                       glm::all(glm::lessThan(h.voxel, lo + e.minCorner.w)));
                        if (visible)
                            quad += albedo / float(M_PI) * glm::vec3(e.radiance) * cx * cy /
                                    (dist * dist) * dA;
                    }
            }
        }
        // Reference mean and its standard error from the independent runs (luminance).
        double mean = 0.0, var = 0.0;
        for (const auto& img : images) mean += luminance(img[i]) / runs;
        for (const auto& img : images)
            var += (luminance(img[i]) - mean) * (luminance(img[i]) - mean);
        double stderrRef = std::sqrt(var / (runs - 1) / runs);
        double expected = luminance(glm::vec4(quad, 0.0f));
        double deviation = std::abs(mean - expected) / std::max(stderrRef + 0.005 * expected, 1e-6);
        worst = std::max(worst, deviation);
        outliers += deviation > 4.0;
        ++checked;
    }
    std::printf("reference vs quadrature: %d pixels, %d beyond 4 sigma, worst %.2f sigma\n",
                checked, outliers, worst);
    EXPECT_GT(checked, 60);
    EXPECT_EQ(outliers, 0);
}
