// Temporal upsampling (`--display upsampled`, render/upsampling/): the motion vectors it
// reprojects by are exact (GPU against the CPU traversal), a still camera converges to the
// anti-aliased image at the display's size from a quarter of its pixels, and a change of render
// size keeps the display's history.
#include <cmath>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "render/camera.h"
#include "render/upsampling/temporal_upsampling.h"
#include "world/scene_trace.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;

namespace {

// Steps, pillars and a thin slab in the sun: silhouettes against the sky and against the floor
// at many slopes, where a pixel-centre image aliases.
Scene edges() {
    Scene scene = paletteScene(
        {48, 24, 48}, {Material{"light", glm::vec3(0.8f)}, Material{"dark", glm::vec3(0.1f)}},
        false);
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 1, 48}}, 1);
    for (int i = 0; i < 6; ++i) {
        const int x = 4 + i * 7;
        fillBox(scene.grid, Box{{x, 1, 8 + i}, {x + 3, 3 + 3 * i, 11 + i}}, i % 2 ? 1 : 2);
    }
    fillBox(scene.grid, Box{{6, 10, 30}, {40, 11, 33}}, 2);
    scene.sky.sunDirection = glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f));
    scene.cameras.push_back(
        CameraPreset{"view", {24.0f, 16.0f, -14.0f}, {22.0f, 4.0f, 20.0f}, 55.0f});
    scene.grid.clearDirty();
    return scene;
}

LightingSettings display(engine::lighting::Display mode) {
    LightingSettings l = kPreview;
    l.display.mode = mode;
    return l;
}

FrameSettings upsampledFrame(std::uint32_t render, std::uint32_t display) {
    FrameSettings f = frame(render);
    f.displayWidth = f.displayHeight = display;
    return f;
}

// The box-filtered truth at `size`: pixel-centre frames at 4x the size, averaged 4x4.
std::vector<glm::vec4> boxFiltered(Scene& scene, std::uint32_t size) {
    const FrameImages fine = renderOnce(scene, scene.camera(), frame(size * 4), kPreview);
    std::vector<glm::vec4> out(std::size_t(size) * size, glm::vec4(0.0f));
    for (std::uint32_t y = 0; y < size * 4; ++y)
        for (std::uint32_t x = 0; x < size * 4; ++x)
            out[(y / 4) * size + x / 4] += fine.radiance[std::size_t(y) * size * 4 + x] / 16.0f;
    return out;
}

// The render-size image blown up to `size` by pixel replication (what the window blit shows).
std::vector<glm::vec4> replicated(const std::vector<glm::vec4>& image, std::uint32_t from,
                                  std::uint32_t size) {
    std::vector<glm::vec4> out(std::size_t(size) * size);
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x)
            out[std::size_t(y) * size + x] = image[(y * from / size) * from + x * from / size];
    return out;
}

double relativeMae(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& truth) {
    return mae(a, truth) / (meanLuminance(truth) + 1e-9);
}

}  // namespace

class Upsampling : public GpuTest {};

TEST(UpsamplingJitter, HaltonOffsetsCoverThePixel) {
    double sx = 0.0, sy = 0.0;
    for (std::uint32_t i = 1; i <= engine::render::TemporalUpsampling::kJitterPhases; ++i) {
        const glm::vec2 j = engine::render::jitterOffset(i);
        EXPECT_GT(j.x, -0.5f);
        EXPECT_LT(j.x, 0.5f);
        EXPECT_GT(j.y, -0.5f);
        EXPECT_LT(j.y, 0.5f);
        sx += j.x;
        sy += j.y;
    }
    EXPECT_LT(std::abs(sx / 16.0), 1.0 / 16.0);  // centred on the pixel
    EXPECT_LT(std::abs(sy / 16.0), 1.0 / 16.0);
    EXPECT_NEAR(engine::render::jitterOffset(1).x, 0.0f, 1e-6);
    EXPECT_NEAR(engine::render::jitterOffset(1).y, 1.0f / 3.0f - 0.5f, 1e-6);
}

// Every pixel whose surface point the previous camera also saw maps, through the G-buffer's motion
// vector, to an image position where the CPU traversal from the previous camera hits the same
// voxel and face. Disoccluded points (the previous ray stops nearer) are the only exceptions.
TEST_F(Upsampling, ReprojectionIsExact) {
    Scene scene = edges();
    const std::uint32_t size = 64;
    Renderer renderer(gpu_testing::context());
    CameraPreset before = scene.camera();
    CameraPreset after = before;
    after.position += glm::vec3(1.7f, 0.6f, -0.9f);  // a known move, and a turn
    after.target += glm::vec3(-0.8f, 0.3f, 0.5f);
    LightingSettings l = display(engine::lighting::Display::Upsampled);
    renderer.render(scene, before, frame(size), l);
    renderer.render(scene, after, frame(size), l);
    const FrameImages images = renderer.readback();
    const shared::FrameParams prev =
        engine::render::makeFrameParams(before, scene.sky, frame(size));

    int checked = 0, disoccluded = 0, wrong = 0;
    for (std::size_t i = 0; i < images.gbuffer.size(); ++i) {
        const auto& g = images.gbuffer[i];
        if (g.voxel.w >= 6 || g.motion.w == 0.0f) continue;
        const glm::vec2 p(g.motion.x, g.motion.y);
        if (p.x < 0 || p.y < 0 || p.x >= size || p.y >= size) continue;  // out of the old view
        const glm::vec3 dir = engine::render::cameraRayDirectionAt(prev, p);
        const SceneHit hit = traceScene(scene.grid, nullptr, before.position, dir, 1e30f);
        const glm::vec3 point(g.position);
        const float toPoint = glm::length(point - before.position);
        if (hit.hit && hit.t < toPoint - 1e-2f) {
            ++disoccluded;
            continue;
        }
        ++checked;
        if (!hit.hit || hit.voxel != glm::ivec3(g.voxel) || hit.face != std::uint32_t(g.voxel.w))
            ++wrong;
    }
    EXPECT_GT(checked, int(size * size) / 2);
    EXPECT_GT(disoccluded, 0);  // the move uncovers something: the test sees the difference
    EXPECT_EQ(wrong, 0) << "of " << checked;
}

// Render 32x32, display 64x64, 32 still frames: the resolved image is nearer the box-filtered
// truth than the render-size image blown up, by half at least.
TEST_F(Upsampling, StillCameraConvergesToTheAntialiasedImage) {
    Scene scene = edges();
    const std::vector<glm::vec4> truth = boxFiltered(scene, 64);
    const FrameImages raw =
        renderOnce(scene, scene.camera(), frame(32), display(engine::lighting::Display::Raw));
    const double rawError = relativeMae(replicated(raw.radiance, 32, 64), truth);

    Renderer renderer(gpu_testing::context());
    const FrameImages up = renderFrames(
        renderer, scene, display(engine::lighting::Display::Upsampled), upsampledFrame(32, 64), 32);
    ASSERT_EQ(up.displayWidth, 64u);
    ASSERT_EQ(up.display.size(), 64u * 64u);
    ASSERT_EQ(up.rgba8.size(), 64u * 64u);
    const double upError = relativeMae(up.display, truth);
    EXPECT_LT(upError, 0.5 * rawError) << "raw 32x32 blown up " << rawError;
    // And no darker or brighter than the truth.
    EXPECT_NEAR(meanLuminance(up.display) / meanLuminance(truth), 1.0, 0.02);
}

// A new render size keeps what the display has converged to: the frame after the change is
// nearer the truth than a first frame at that size.
TEST_F(Upsampling, ChangingTheRenderSizeKeepsTheDisplayHistory) {
    Scene scene = edges();
    const std::vector<glm::vec4> truth = boxFiltered(scene, 64);
    const LightingSettings l = display(engine::lighting::Display::Upsampled);
    Renderer renderer(gpu_testing::context());
    renderFrames(renderer, scene, l, upsampledFrame(32, 64), 24);
    const FrameImages kept = renderFrames(renderer, scene, l, upsampledFrame(48, 64), 1);
    Renderer fresh(gpu_testing::context());
    const FrameImages first = renderFrames(fresh, scene, l, upsampledFrame(48, 64), 1);
    EXPECT_LT(relativeMae(kept.display, truth), 0.8 * relativeMae(first.display, truth));
}
