// The frame plan (render/frame_plan.h): for every combination of method, indirect mode, sky,
// sampling, light tiles, accumulation, exposure and display, the memory plan reserves memory for
// exactly the techniques the frame runs, the shader features of a technique are on only when it
// runs, and both agree with the settings' own answers to "is X on?" (lighting/lighting_settings.h).
#include "render/frame_plan.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "lighting/lighting_knobs.h"
#include "render/memory_plan.h"
#include "render/shader_features.h"
#include "shared/shader_features.h"
#include "world/scene.h"

using namespace engine::lighting;
using engine::render::FramePlan;
using engine::render::MemoryPlan;
using engine::render::ShaderFeatures;

namespace {

KnobValue option(std::string_view name, std::string text) {
    const Knob* k = knobForOption(name);
    EXPECT_NE(k, nullptr) << name;
    return {k, std::move(text), std::string("--") + std::string(name)};
}

bool reserves(const MemoryPlan& memory, std::string_view technique) {
    return std::any_of(memory.techniques.begin(), memory.techniques.end(),
                       [&](const auto& t) { return t.first == technique; });
}

// The settings' answer to "does `technique` run?", independent of the frame plan.
bool settingsSayRuns(std::string_view technique, const LightingSettings& l) {
    if (technique == "light_tiles") return usesLightTiles(l);
    if (technique == "regir") return usesRegir(l);
    if (technique == "preview") return l.method == Method::Preview;
    if (technique == "restir") return resamples(l);
    if (technique == "baselines") return samplesLightsPerPixel(l);
    if (technique == "reference") return l.method == Method::Reference;
    if (technique == "sky") return usesSkyTerm(l);
    if (technique == "path") return usesPath(l);
    if (technique == "vct") return usesVct(l);
    if (technique == "cache") return usesCache(l);
    if (technique == "accumulation") return accumulates(l);
    if (technique == "exposure") return usesAutoExposure(l);
    if (technique == "denoiser") return denoises(l);
    if (technique == "upsampling") return reconstructs(l);
    ADD_FAILURE() << "a technique the test does not know: " << technique;
    return false;
}

// The frame plan, the memory plan and the shader features of one combination of knob values.
void checkAgreement(const std::vector<KnobValue>& values, const std::string& what) {
    const engine::world::Scene scene;  // a small world, which the sky's keys cover
    const glm::uvec2 size(64, 48);
    auto l = mergeLighting(LightingSettings{}, values);
    ASSERT_TRUE(l.ok()) << l.error().message;
    const FramePlan plan = engine::render::planFrame(*l, engine::render::sceneShape(scene), size);
    const MemoryPlan memory = engine::render::planMemory(scene, size, *l);
    const ShaderFeatures features = engine::render::shaderFeatures(*l, false);
    for (const FramePlan::Step& step : plan.steps) {
        const std::string_view name = step.technique->name;
        EXPECT_EQ(step.plan.runs, settingsSayRuns(name, *l)) << name << ": " << what;
        EXPECT_EQ(reserves(memory, name), step.plan.runs && step.plan.deviceBytes > 0)
            << name << " in the memory plan: " << what;
        for (const auto& [feature, value] : step.plan.features) {
            // A technique's feature: its value when it runs, else compiled out; on only with its
            // memory planned.
            EXPECT_EQ(features[feature], step.plan.runs ? value : 0u)
                << "feature " << feature << " of " << name << ": " << what;
            if (features[feature] != 0u && step.plan.deviceBytes > 0) {
                EXPECT_TRUE(reserves(memory, name)) << "feature " << feature << ": " << what;
            }
        }
    }
}

}  // namespace

TEST(FramePlan, MemoryPlanAndShaderFeaturesAgreeForEveryCombination) {
    // Every value of every knob that decides which techniques run.
    const std::vector<std::pair<const char*, std::vector<const char*>>> knobs{
        {"method",
         {"preview", "restir", "restir-unbiased", "ris", "uniform", "bruteforce", "reference"}},
        {"indirect", {"none", "cache", "path", "reference", "vct"}},
        {"sky", {"none", "dvf", "reference"}},
        {"sampling", {"uniform", "power", "regir"}},
        {"light-tiles", {"off", "on"}},
        {"accumulate", {"off", "on"}},
        {"auto-exposure", {"off", "on"}},
        {"display", {"raw", "upsampled", "denoised"}},
    };
    std::vector<std::size_t> pick(knobs.size(), 0);  // an odometer over the knobs' values
    int combinations = 0;
    for (bool more = true; more; ++combinations) {
        std::vector<KnobValue> values;
        std::string what;
        for (std::size_t k = 0; k < knobs.size(); ++k) {
            values.push_back(option(knobs[k].first, knobs[k].second[pick[k]]));
            what += std::string(knobs[k].first) + " " + knobs[k].second[pick[k]] + " ";
        }
        checkAgreement(values, what);
        more = false;
        for (std::size_t k = 0; k < knobs.size() && !more; ++k) {
            pick[k] = (pick[k] + 1) % knobs[k].second.size();
            more = pick[k] != 0;
        }
    }
    EXPECT_EQ(combinations, 7 * 5 * 3 * 3 * 2 * 2 * 2 * 3);
}

// Exactly one technique lights the frame directly, whatever the settings.
TEST(FramePlan, OneDirectMethodRuns) {
    for (Method m : {Method::Preview, Method::Restir, Method::Ris, Method::Uniform,
                     Method::BruteForce, Method::Reference}) {
        LightingSettings l;
        l.method = m;
        const FramePlan plan = engine::render::planFrame(l, {}, {8, 8});
        int direct = 0;
        for (const char* name : {"preview", "restir", "baselines", "reference"})
            direct += plan.runs(name);
        EXPECT_EQ(direct, 1) << methodName(m);
    }
}

// The lighting's description names the direct method, then each term added to it.
TEST(FramePlan, DescriptionNamesTheRunningTechniques) {
    LightingSettings l;
    l.indirect = Indirect::Cache;
    const std::string text = engine::render::describeLighting(l);
    EXPECT_EQ(
        text.rfind("restir biased area M=32 auto bricks temporal spatial 5x30px + cache K=128", 0),
        0u)
        << text;
    l.method = Method::Reference;  // the cache does not run beside the reference
    EXPECT_EQ(engine::render::describeLighting(l), "reference 0 bounce(s)");
}
