// Shader features (render/shader_features.h): the code of the features a frame does not use is
// compiled out of its pipelines. These tests render the same frames with the specialised
// pipelines and with the generic ones, which read every knob at run time: a feature compiled out
// while the frame needs it changes the image.
#include "render/shader_features.h"

#include <algorithm>
#include <cstring>
#include <gtest/gtest.h>

#include "gpu/compute_pipeline.h"
#include "gpu/gpu_test_setup.h"
#include "shared/restir.h"

using namespace gpu_testing;

class ShaderFeatures : public GpuTest {};

namespace {

std::vector<glm::vec4> radianceAfter(engine::world::Scene& scene, const LightingSettings& lighting,
                                     bool specialise) {
    Renderer renderer(context());
    renderer.setSpecializeShaders(specialise);
    return renderFrames(renderer, scene, lighting, frame(48, 32), 3).radiance;
}

}  // namespace

TEST_F(ShaderFeatures, SpecialisedFramesEqualTheGenericOnes) {
    engine::world::Scene scene = loadWorld("sandbox.toml");
    struct Case {
        const char* name;
        LightingSettings lighting;
    };
    std::vector<Case> cases;
    cases.push_back({"restir (defaults)", {}});
    LightingSettings l;
    l.restir.unbiased = 1u;
    cases.push_back({"restir-unbiased", l});
    l = {};
    l.area = false;
    cases.push_back({"point mode", l});
    l = {};
    l.byPower = false;
    cases.push_back({"uniform candidates", l});
    l = {};
    l.regir.enabled = 1u;
    cases.push_back({"regir", l});
    l = {};
    l.restir.lightTiles = 1u;
    l.indirect = engine::lighting::Indirect::Cache;
    cases.push_back({"light tiles + cache", l});
    l = {};
    l.indirect = engine::lighting::Indirect::Cache;
    l.cache.bounces = 2;
    cases.push_back({"cache, two bounces", l});
    l = {};
    l.indirect = engine::lighting::Indirect::Cache;
    l.cache.fallbackRadius = 4;
    cases.push_back({"cache with the gather's fallback", l});
    l = {};
    l.restir.candidateVisibility = 0u;
    cases.push_back({"no candidate visibility", l});
    for (const Case& c : cases) {
        const std::vector<glm::vec4> generic = radianceAfter(scene, c.lighting, false);
        const std::vector<glm::vec4> specialised = radianceAfter(scene, c.lighting, true);
        ASSERT_EQ(generic.size(), specialised.size());
        EXPECT_EQ(
            0, std::memcmp(generic.data(), specialised.data(), generic.size() * sizeof(glm::vec4)))
            << c.name;
        EXPECT_GT(meanLuminance(specialised), 0.0) << c.name;
    }
    // The sandbox above has an object (its cart): the dynamic grid's code stays. A world without
    // objects compiles it out, and must render the same.
    engine::world::Scene cornell = loadWorld("cornell.toml");
    ASSERT_FALSE(cornell.dynamic.present());
    LightingSettings cached;
    cached.indirect = engine::lighting::Indirect::Cache;
    for (const LightingSettings& lighting : {LightingSettings{}, cached}) {
        const std::vector<glm::vec4> generic = radianceAfter(cornell, lighting, false);
        const std::vector<glm::vec4> specialised = radianceAfter(cornell, lighting, true);
        ASSERT_EQ(generic.size(), specialised.size());
        EXPECT_EQ(
            0, std::memcmp(generic.data(), specialised.data(), generic.size() * sizeof(glm::vec4)))
            << "cornell without objects, indirect " << int(lighting.indirect);
        EXPECT_GT(meanLuminance(specialised), 0.0);
    }
}

TEST_F(ShaderFeatures, AFrameUsesOnlyTheFeaturesItsSettingsAskFor) {
    const engine::render::ShaderFeatures defaults = engine::render::shaderFeatures({}, true);
    EXPECT_EQ(defaults[FEATURE_REGIR], 0u);
    EXPECT_EQ(defaults[FEATURE_LIGHT_TILES], 0u);
    EXPECT_EQ(defaults[FEATURE_UNIFORM_SAMPLING], 0u);
    EXPECT_EQ(defaults[FEATURE_POINT_LIGHTS], 0u);
    EXPECT_EQ(defaults[FEATURE_CANDIDATE_VISIBILITY], 1u);
    EXPECT_EQ(defaults[FEATURE_UNBIASED], 0u);
    EXPECT_EQ(defaults[FEATURE_CACHE_MULTI_BOUNCE], 0u);
    EXPECT_EQ(defaults[FEATURE_CACHE_FALLBACK], 0u);  // no cache, none of its code
    EXPECT_EQ(defaults[FEATURE_DYNAMIC_GRID], 1u);
    EXPECT_EQ(engine::render::shaderFeatures({}, false)[FEATURE_DYNAMIC_GRID], 0u);
    LightingSettings cache;
    cache.indirect = engine::lighting::Indirect::Cache;
    EXPECT_EQ(engine::render::shaderFeatures(cache, true)[FEATURE_CACHE_FALLBACK],
              1u);  // on by default (docs/IRRADIANCE_CACHE.md)
    LightingSettings noFallback = cache;
    noFallback.cache.fallbackRadius = 0u;
    EXPECT_EQ(engine::render::shaderFeatures(noFallback, true)[FEATURE_CACHE_FALLBACK], 0u);
    LightingSettings unbiased;
    unbiased.restir.unbiased = 1u;
    unbiased.restir.candidateVisibility = 0u;  // the unbiased mode tests its candidates anyway
    EXPECT_EQ(engine::render::shaderFeatures(unbiased, true)[FEATURE_UNBIASED], 1u);
    EXPECT_EQ(engine::render::shaderFeatures(unbiased, true)[FEATURE_CANDIDATE_VISIBILITY], 1u);
}

TEST_F(ShaderFeatures, PipelinesFindTheConstantsTheirShaderDeclares) {
    engine::gpu::ComputePipeline initial(context(), "restir/initial_candidates",
                                         shared::RESTIR_INITIAL_BINDING_OUT + 1);
    const std::vector<std::uint32_t>& ids = initial.specializationIds();
    for (std::uint32_t id :
         {FEATURE_REGIR, FEATURE_LIGHT_TILES, FEATURE_POINT_LIGHTS, FEATURE_CANDIDATE_VISIBILITY}) {
        EXPECT_TRUE(std::find(ids.begin(), ids.end(), id) != ids.end()) << "constant_id " << id;
    }
    engine::gpu::ComputePipeline tonemap(context(), "post/tonemap", 4);
    EXPECT_TRUE(tonemap.specializationIds().empty());
}
