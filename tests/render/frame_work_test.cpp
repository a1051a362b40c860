// The work counted per frame (render/frame_work.h) is the work the passes issue for the settings,
// worked out by hand from the shaders for a small image: the benches' equal-cost counts rest on
// these numbers, so each method's are pinned exactly.
#include "render/frame_work.h"

#include <gtest/gtest.h>

using engine::lighting::LightingSettings;
using engine::lighting::Method;
using engine::render::FrameWork;
using engine::render::frameWork;
using engine::render::WorkKind;

namespace {

constexpr glm::uvec2 kSize{8, 4};  // 32 pixels
constexpr double kPixels = 32.0;

void expectCounts(const FrameWork& w, double pixels, double samples, double candidates, double rays,
                  double taps) {
    EXPECT_EQ(w[WorkKind::Pixels], pixels * kPixels);
    EXPECT_EQ(w[WorkKind::LightSamples], samples * kPixels);
    EXPECT_EQ(w[WorkKind::Candidates], candidates * kPixels);
    EXPECT_EQ(w[WorkKind::ShadowRays], rays * kPixels);
    EXPECT_EQ(w[WorkKind::ReuseTaps], taps * kPixels);
}

}  // namespace

TEST(FrameWork, UniformIssuesOneSampleAndShadowRayPerRay) {
    LightingSettings l;
    l.method = Method::Uniform;
    l.shadowRays = 7;
    expectCounts(frameWork(l, kSize, 100), 1, 7, 0, 0, 0);
    l.shadowRays = 0;  // the shader takes at least one
    expectCounts(frameWork(l, kSize, 100), 1, 1, 0, 0, 0);
}

TEST(FrameWork, BruteForceSamplesEveryEmitter) {
    LightingSettings l;
    l.method = Method::BruteForce;
    expectCounts(frameWork(l, kSize, 13), 1, 13, 0, 0, 0);
}

TEST(FrameWork, RisIsCandidatesAndTheShadingRayWithoutReuse) {
    LightingSettings l;
    l.method = Method::Ris;
    l.restir.candidates = 24;
    // restirParams turns reuse and the candidate shadow test off for RIS, whatever the knobs say.
    expectCounts(frameWork(l, kSize, 100), 1, 0, 24, 1, 0);
}

TEST(FrameWork, RestirCountsVisibilityTemporalAndSpatialTaps) {
    LightingSettings l;  // the defaults: M 32, candidate visibility, temporal, 5 spatial taps
    ASSERT_EQ(l.method, Method::Restir);
    ASSERT_EQ(l.restir.candidates, 32u);
    ASSERT_EQ(l.restir.spatialTaps, 5u);
    // Rays: candidate test + shading; taps: last frame's reservoir + 2 per spatial neighbour.
    expectCounts(frameWork(l, kSize, 100), 1, 0, 32, 2, 1 + 2 * 5);
    l.restir.candidateVisibility = 0;
    l.restir.temporal = 0;
    l.restir.spatialTaps = 3;
    expectCounts(frameWork(l, kSize, 100), 1, 0, 32, 1, 2 * 3);
    l.restir.spatial = 0;
    expectCounts(frameWork(l, kSize, 100), 1, 0, 32, 1, 0);
}

TEST(FrameWork, UnbiasedRestirAddsTheTemporalShadowRayAndEvaluation) {
    LightingSettings l;
    l.restir.unbiased = 1;
    l.restir.candidateVisibility = 0;  // unbiased forces the candidate test on
    expectCounts(frameWork(l, kSize, 100), 1, 0, 32, 3, 2 + 2 * 5);
}

TEST(FrameWork, PreviewAndReferenceCountPixelsOnly) {
    LightingSettings l;
    l.method = Method::Preview;
    expectCounts(frameWork(l, kSize, 100), 1, 0, 0, 0, 0);
    l.method = Method::Reference;
    expectCounts(frameWork(l, {3, 5}, 100), 15.0 / kPixels, 0, 0, 0, 0);
}
