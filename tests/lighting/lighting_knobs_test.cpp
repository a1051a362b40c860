// The one settings path: knob tables, the merge of a scene's settings with overrides, and the
// validation every entry point shares.
#include "lighting/lighting_knobs.h"

#include <gtest/gtest.h>

#include "render/frame_plan.h"
#include "scene/scene_file.h"
#include "scene/scene_lighting.h"
#include "world/scene.h"

using namespace engine::lighting;
using engine::Status;

namespace {

KnobValue option(std::string_view name, std::string text) {
    const Knob* k = knobForOption(name);
    EXPECT_NE(k, nullptr) << name;
    return {k, std::move(text), std::string("--") + std::string(name)};
}

}  // namespace

TEST(LightingKnobs, MergingNothingGivesTheDefaults) {
    auto merged = mergeLighting(std::span<const std::vector<KnobValue>>{});
    ASSERT_TRUE(merged.ok()) << merged.error().message;
    EXPECT_EQ(*merged, LightingSettings{});
    EXPECT_TRUE(validate(LightingSettings{}).ok());
}

TEST(LightingKnobs, EveryKnobReadsBackWhatItWrites) {
    LightingSettings s;
    s.method = Method::Uniform;
    s.cache.alpha = 0.07f;
    s.cache.budgetBytes = 96ull << 20;
    s.restir.spatialRadius = 12.5f;
    for (const KnobGroup& g : knobGroups()) {
        for (const Knob& k : g.knobs) {
            LightingSettings copy = s;
            ASSERT_TRUE(setKnob(k, copy, knobText(k, s)).ok()) << k.name;
            EXPECT_EQ(copy, s) << k.name << " = " << knobText(k, s);
        }
    }
}

TEST(LightingKnobs, OutOfRangeIsRefusedTheSameWayFromTextAndFromCode) {
    LightingSettings s;
    Status fromText = setKnob(*knobForOption("candidates"), s, "0");
    ASSERT_FALSE(fromText.ok());
    s.restir.candidates = 0;  // as a bench or the HUD would set it
    Status fromCode = validate(s);
    ASSERT_FALSE(fromCode.ok());
    EXPECT_EQ(fromText.error().message, fromCode.error().message);
    EXPECT_NE(fromText.error().message.find("candidates must be positive, not 0; allowed: 1..1024"),
              std::string::npos);

    LightingSettings c;
    c.cache.raysPerUpdate = 7;  // not a divisor of 128
    EXPECT_FALSE(validate(c).ok());
    EXPECT_FALSE(mergeLighting(c, {}).ok());
    EXPECT_FALSE(setKnob(*knobForOption("cache-alpha"), c, "nan").ok());
    EXPECT_FALSE(setKnob(*knobForOption("mode"), c, "spot").ok());
}

// `vox play --cache-rays 8` without --indirect lost --cache-rays: the sandbox replaced the cache
// settings with the scene's after the command line had been read.
TEST(LightingKnobs, CommandLineOverridesTheSceneKnobByKnob) {
    engine::world::Scene scene;
    scene.indirect = {{"mode", "cache"}, {"alpha", "0.1"}};
    std::vector<KnobValue> cli{option("cache-rays", "8")};
    auto s = engine::scene::lightingFor(&scene, cli);
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(s->indirect, Indirect::Cache);  // the scene's
    EXPECT_EQ(s->cache.alpha, 0.1f);          // the scene's
    EXPECT_EQ(s->cache.raysPerUpdate, 8u);    // the command line's

    cli.push_back(option("indirect", "none"));
    auto none = engine::scene::lightingFor(&scene, cli);
    ASSERT_TRUE(none.ok());
    EXPECT_EQ(none->indirect, Indirect::None);
}

TEST(LightingKnobs, MethodsImplyTheirSettings) {
    auto ris = mergeLighting(LightingSettings{}, std::vector<KnobValue>{option("method", "ris")});
    ASSERT_TRUE(ris.ok());
    EXPECT_FALSE(ris->restir.temporal);
    EXPECT_FALSE(ris->restir.spatial);
    auto unbiased = mergeLighting(LightingSettings{},
                                  std::vector<KnobValue>{option("method", "restir-unbiased")});
    ASSERT_TRUE(unbiased.ok());
    EXPECT_EQ(unbiased->method, Method::Restir);
    EXPECT_TRUE(unbiased->restir.unbiased);
    auto reference =
        mergeLighting(LightingSettings{}, std::vector<KnobValue>{option("indirect", "reference")});
    ASSERT_TRUE(reference.ok());
    EXPECT_EQ(reference->method, Method::Reference);
    EXPECT_GE(reference->bounces, 1u);
}

TEST(LightingKnobs, ErrorsNameWhereTheValueCameFrom) {
    auto bad = mergeLighting(LightingSettings{}, std::vector<KnobValue>{option("spatial", "5")});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message.rfind("--spatial: ", 0), 0u) << bad.error().message;
}

// The path-traced indirect term's knobs come from their rows like every other: a scene's
// [indirect] keys (path_spp...), the command line's --path-* options, the same ranges.
TEST(LightingKnobs, PathIndirectKnobsFromSceneAndCommandLine) {
    engine::world::Scene scene;
    scene.indirect = {{"mode", "path"}, {"path_spp", "4"}};
    auto s =
        engine::scene::lightingFor(&scene, std::vector<KnobValue>{option("path-bounces", "2")});
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(s->indirect, Indirect::Path);
    EXPECT_EQ(s->path.samples, 4u);   // the scene's
    EXPECT_EQ(s->path.bounces, 2u);   // the command line's
    EXPECT_TRUE(s->path.accumulate);  // the default
    EXPECT_NE(engine::render::describeLighting(*s).find("path 4 spp 2 bounce(s)"),
              std::string::npos)
        << engine::render::describeLighting(*s);

    auto bad = mergeLighting(LightingSettings{}, std::vector<KnobValue>{option("path-spp", "0")});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message.rfind("--path-spp: ", 0), 0u) << bad.error().message;
}

// --sampling regir is ReGIR's switch beside drawing by power (its cells draw by power); uniform and
// power turn it off again, and the lighting's description (render::describeLighting) names it.
TEST(LightingKnobs, SamplingChoosesUniformPowerOrRegir) {
    LightingSettings s;
    const Knob& sampling = *knobForOption("sampling");
    ASSERT_TRUE(setKnob(sampling, s, "regir").ok());
    EXPECT_TRUE(s.byPower);
    EXPECT_EQ(s.regir.enabled, 1u);
    EXPECT_EQ(knobText(sampling, s), "regir");
    EXPECT_NE(engine::render::describeLighting(s).find("regir"), std::string::npos);
    ASSERT_TRUE(setKnob(sampling, s, "uniform").ok());
    EXPECT_FALSE(s.byPower);
    EXPECT_EQ(s.regir.enabled, 0u);
    ASSERT_TRUE(setKnob(sampling, s, "power").ok());
    EXPECT_TRUE(s.byPower);
    EXPECT_EQ(s.regir.enabled, 0u);
    EXPECT_FALSE(setKnob(sampling, s, "tree").ok());
    EXPECT_FALSE(setKnob(*knobForOption("regir-cell"), s, "0").ok());
}

// --sampling auto is the default: ReSTIR's description says so, the knob writes it back, and a
// scene file's [indirect] sampling and the command line set it and override it both ways; the
// renderer resolves it per scene (render/sampling_choice.h).
TEST(LightingKnobs, SamplingAutoIsTheDefaultAndRoundTrips) {
    const Knob& sampling = *knobForOption("sampling");
    const LightingSettings defaults;
    EXPECT_TRUE(defaults.autoSampling);
    EXPECT_TRUE(defaults.byPower);
    EXPECT_EQ(knobText(sampling, defaults), "auto");
    EXPECT_NE(engine::render::describeLighting(defaults).find(" auto "), std::string::npos)
        << engine::render::describeLighting(defaults);

    const char* text = R"([world]
name = "auto_sampling"
size = [32, 32, 32]
[indirect]
sampling = "power"
)";
    auto scene = engine::scene::loadSceneText(text, "auto_sampling.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto fromScene = engine::scene::lightingFor(&*scene, std::vector<KnobValue>{});
    ASSERT_TRUE(fromScene.ok()) << fromScene.error().message;
    EXPECT_FALSE(fromScene->autoSampling);
    EXPECT_EQ(knobText(sampling, *fromScene), "power");
    auto fromCli =
        engine::scene::lightingFor(&*scene, std::vector<KnobValue>{option("sampling", "auto")});
    ASSERT_TRUE(fromCli.ok()) << fromCli.error().message;
    EXPECT_TRUE(fromCli->autoSampling);
    EXPECT_EQ(knobText(sampling, *fromCli), "auto");

    scene->indirect = {{"sampling", "auto"}};
    auto reread = engine::scene::loadSceneText(engine::scene::sceneText(*scene), "again.toml");
    ASSERT_TRUE(reread.ok()) << reread.error().message;
    auto autoAgain = engine::scene::lightingFor(&*reread, std::vector<KnobValue>{});
    ASSERT_TRUE(autoAgain.ok()) << autoAgain.error().message;
    EXPECT_EQ(*autoAgain, defaults);
    auto regir =
        engine::scene::lightingFor(&*reread, std::vector<KnobValue>{option("sampling", "regir")});
    ASSERT_TRUE(regir.ok()) << regir.error().message;
    EXPECT_FALSE(regir->autoSampling);
    EXPECT_EQ(regir->regir.enabled, 1u);
}

// Voxel cone tracing's knobs likewise: [indirect] mode = "vct" and vct_* keys, --vct-* options.
TEST(LightingKnobs, VctKnobsFromSceneAndCommandLine) {
    engine::world::Scene scene;
    scene.indirect = {{"mode", "vct"}, {"vct_levels", "3"}};
    auto s = engine::scene::lightingFor(
        &scene, std::vector<KnobValue>{option("vct-leak-mitigation", "off")});
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(s->indirect, Indirect::Vct);
    EXPECT_EQ(s->vct.levels, 3u);         // the scene's
    EXPECT_FALSE(s->vct.leakMitigation);  // the command line's
    EXPECT_FALSE(s->vct.extraBounce);     // the default
    EXPECT_NE(
        engine::render::describeLighting(*s).find("vct 3 level(s) refresh 1/8 no leak mitigation"),
        std::string::npos)
        << engine::render::describeLighting(*s);

    auto bad = mergeLighting(LightingSettings{}, std::vector<KnobValue>{option("vct-levels", "5")});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message.rfind("--vct-levels: ", 0), 0u) << bad.error().message;
}
