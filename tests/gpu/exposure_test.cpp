// Automatic exposure (`--auto-exposure on`, render/exposure/): the displayed image of a scene does
// not depend on how bright its light is (metered from a histogram of the lit image), the EXR's
// radiance is untouched, and a change of brightness is followed a fraction of the way per frame.
#include <cmath>
#include <gtest/gtest.h>

#include "gpu/gpu_test_setup.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;

namespace {

// A floor and a block under the sun and sky, whose light is scaled by `brightness`.
Scene sunlit(float brightness) {
    Scene scene = paletteScene(
        {32, 16, 32},
        {Material{"grey", glm::vec3(0.6f)}, Material{"red", glm::vec3(0.7f, 0.2f, 0.1f)}}, false);
    fillBox(scene.grid, Box{{0, 0, 0}, {32, 2, 32}}, 1);
    fillBox(scene.grid, Box{{12, 2, 12}, {20, 9, 20}}, 2);
    scene.sky.sunRadiance *= brightness;
    scene.sky.skyRadiance *= brightness;
    scene.cameras.push_back(
        CameraPreset{"above", {16.0f, 20.0f, -8.0f}, {16.0f, 4.0f, 16.0f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

LightingSettings autoExposure(bool on, float adaptation = 0.1f) {
    LightingSettings l = kPreview;
    l.exposure.automatic = on;
    l.exposure.adaptation = adaptation;
    return l;
}

// Mean of the displayed image's channels, 0..1.
double displayedMean(const FrameImages& f) {
    double sum = 0.0;
    for (std::uint32_t p : f.rgba8)
        sum += double((p & 0xffu) + ((p >> 8) & 0xffu) + ((p >> 16) & 0xffu)) / 765.0;
    return sum / double(f.rgba8.size());
}

}  // namespace

class AutoExposure : public GpuTest {};

// Sixteen times the light is four stops, sixteen histogram bins: the metered exposure is a
// sixteenth and the displayed image the same (within 1 % of its mean); with the fixed exposure
// the brighter scene is washed out. The radiance itself is sixteen times brighter either way.
TEST_F(AutoExposure, TheDisplayedImageDoesNotDependOnTheLightsBrightness) {
    Scene dim = sunlit(1.0f), bright = sunlit(16.0f);
    const FrameImages a = renderOnce(dim, dim.camera(), frame(48), autoExposure(true));
    const FrameImages b = renderOnce(bright, bright.camera(), frame(48), autoExposure(true));
    const FrameImages fixedBright =
        renderOnce(bright, bright.camera(), frame(48), autoExposure(false));
    std::printf("displayed mean: dim auto %.3f, 16x auto %.3f, 16x fixed %.3f\n", displayedMean(a),
                displayedMean(b), displayedMean(fixedBright));
    EXPECT_NEAR(displayedMean(b) / displayedMean(a), 1.0, 0.01);
    EXPECT_GT(displayedMean(fixedBright), displayedMean(a) * 1.2);
    EXPECT_NEAR(meanLuminance(b.radiance) / meanLuminance(a.radiance), 16.0, 0.05);
}

// After the light steps up 16x, an adaptation of 0.5 per frame halves the remaining stops each
// frame: the first frame after the step is brighter than the settled image, and six frames later
// the image has settled (within 2 %). Adaptation 1 settles at once.
TEST_F(AutoExposure, ABrightnessStepIsFollowedAFractionPerFrame) {
    Scene scene = sunlit(1.0f);
    const FrameImages settled =
        renderOnce(scene, scene.camera(), frame(32), autoExposure(true, 0.5f));
    for (float adaptation : {0.5f, 1.0f}) {
        Scene s = sunlit(1.0f);
        Renderer r(gpu_testing::context());
        renderFrames(r, s, autoExposure(true, adaptation), frame(32), 3);
        s.sky.sunRadiance *= 16.0f;
        s.sky.skyRadiance *= 16.0f;
        const double first =
            displayedMean(renderFrames(r, s, autoExposure(true, adaptation), frame(32), 1));
        const double later =
            displayedMean(renderFrames(r, s, autoExposure(true, adaptation), frame(32), 6));
        std::printf("adaptation %.1f: settled %.3f, first frame after the step %.3f, 7th %.3f\n",
                    adaptation, displayedMean(settled), first, later);
        if (adaptation < 1.0f)
            EXPECT_GT(first, displayedMean(settled) * 1.2);
        else
            EXPECT_NEAR(first / displayedMean(settled), 1.0, 0.01);
        EXPECT_NEAR(later / displayedMean(settled), 1.0, 0.02);
    }
}
