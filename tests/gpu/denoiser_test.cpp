// The denoiser (`--display denoised`, render/denoiser/): it keeps the lighting's energy (the
// filtered image's mean is the unfiltered one's over many frames) and its edges (an albedo
// checkerboard and a hard shadow keep their contrast), and it removes most of the noise of one
// light sample per pixel.
#include <cmath>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;
using engine::lighting::Display;

namespace {

// A floor of two albedos in a 2-voxel checkerboard, a wall casting a hard sun shadow across it,
// and four small lamps: one ReSTIR sample per pixel is noisy, the sun's edge is sharp.
Scene checkerboard() {
    Scene scene =
        paletteScene({32, 16, 32},
                     {Material{"light", glm::vec3(0.8f)}, Material{"dark", glm::vec3(0.2f)},
                      Material{"lamp", glm::vec3(0.7f), glm::vec3(1.0f, 0.9f, 0.7f), 8.0f}},
                     false);
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) scene.grid.set({x, 0, z}, ((x / 2 + z / 2) % 2) ? 1 : 2);
    fillBox(scene.grid, Box{{0, 1, 20}, {32, 9, 21}}, 1);  // the wall
    for (int i = 0; i < 4; ++i) fillBox(scene.grid, Box{{4 + 7 * i, 5, 6}, {5 + 7 * i, 6, 7}}, 3);
    scene.sky.sunDirection = glm::normalize(glm::vec3(0.0f, 1.0f, 1.2f));  // shadow towards -z
    scene.sky.skyRadiance = glm::vec3(0.0f);
    scene.cameras.push_back(
        CameraPreset{"down", {16.0f, 26.0f, 10.0f}, {16.0f, 0.0f, 14.0f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

LightingSettings restir(Display mode, bool jitter = true) {
    LightingSettings l;
    l.method = engine::lighting::Method::Restir;
    l.display.mode = mode;
    l.display.jitter = jitter;
    return l;
}

// The mean luminance of the render-size radiance (the denoiser's output, before the resolve) over
// `frames` frames.
double meanOverFrames(Scene& scene, const LightingSettings& l, std::uint32_t size, int frames) {
    Renderer renderer(gpu_testing::context());
    double sum = 0.0;
    for (int i = 0; i < frames; ++i) {
        renderer.render(scene, scene.camera(), frame(size), l);
        sum += meanLuminance(renderer.readback().radiance);
    }
    return sum / frames;
}

}  // namespace

class Denoiser : public GpuTest {};

// Over 48 frames the denoised mean is the unfiltered one's within 1 % on three worlds. Both
// jitter their primary rays the same way (the unfiltered one with --display upsampled): the mean of
// jittered samples is the box-filtered image's, which on a 64x64 Cornell box is 4 % below the
// pixel centres' (its lamp's edge), so that is what the denoiser must keep.
TEST_F(Denoiser, KeepsTheEnergy) {
    struct Case {
        Scene scene;
        const char* name;
    };
    Case cases[] = {{checkerboard(), "checkerboard"},
                    {loadWorld("cornell"), "cornell"},
                    {loadWorld("apartments"), "apartments"}};
    for (Case& c : cases) {
        const double raw = meanOverFrames(c.scene, restir(Display::Upsampled), 64, 48);
        const double denoised = meanOverFrames(c.scene, restir(Display::Denoised), 64, 48);
        ASSERT_GT(raw, 1e-4) << c.name;
        std::printf("%s: denoised / unfiltered mean %.5f\n", c.name, denoised / raw);
        EXPECT_NEAR(denoised / raw, 1.0, 0.01) << c.name;
    }
}

// The checkerboard's and the shadow's contrast after 32 denoised frames is the converged image's
// within 5 %: the filter does not cross voxel-face planes, and demodulation keeps the albedo out
// of it. The converged image is the mean of 256 raw frames; both shade pixel centres (no jitter),
// so they see the same edges.
TEST_F(Denoiser, KeepsVoxelFaceAndShadowEdges) {
    Scene scene = checkerboard();
    const std::uint32_t size = 96;
    LightingSettings truthSettings = restir(Display::Raw);
    truthSettings.accumulation.enabled = true;
    Renderer truthRenderer(gpu_testing::context());
    const FrameImages truth = renderFrames(truthRenderer, scene, truthSettings, frame(size), 256);
    Renderer renderer(gpu_testing::context());
    const FrameImages denoised =
        renderFrames(renderer, scene, restir(Display::Denoised, false), frame(size), 32);

    // Contrast between neighbouring pixels on different floor voxels (different albedo, or lit and
    // shadowed): the sum of |difference| over the pairs the G-buffer says straddle such an edge.
    auto edgeContrast = [&](const std::vector<glm::vec4>& image) {
        double sum = 0.0;
        for (std::uint32_t y = 0; y < size; ++y) {
            for (std::uint32_t x = 0; x + 1 < size; ++x) {
                const std::size_t a = std::size_t(y) * size + x, b = a + 1;
                const auto& ga = truth.gbuffer[a];
                const auto& gb = truth.gbuffer[b];
                if (ga.voxel.y != 0 || gb.voxel.y != 0 || ga.voxel.w != 3 || gb.voxel.w != 3)
                    continue;
                if (glm::ivec3(ga.voxel) == glm::ivec3(gb.voxel)) continue;
                sum += std::abs(luminance(image[a]) - luminance(image[b]));
            }
        }
        return sum;
    };
    const double truthContrast = edgeContrast(truth.radiance);
    ASSERT_GT(truthContrast, 1.0);
    EXPECT_NEAR(edgeContrast(denoised.radiance) / truthContrast, 1.0, 0.05);
    // And most of the noise is gone: nearer the converged image than one raw frame.
    Renderer rawRenderer(gpu_testing::context());
    const FrameImages raw = renderFrames(rawRenderer, scene, restir(Display::Raw), frame(size), 32);
    EXPECT_LT(mae(denoised.radiance, truth.radiance), 0.5 * mae(raw.radiance, truth.radiance));
}
