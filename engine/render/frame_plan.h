// FramePlan: a frame's settings and scene turned into which techniques run, with their shader
// features and their memory — the one answer to "is X on?". The renderer runs the planned
// techniques; the shader features (shader_features.h) and the memory plan (memory_plan.h) read
// the same plan, so neither can count a technique the frame does not run, or miss one it does.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/shader_features.h"
#include "render/technique_registry.h"

namespace engine::render {

struct FramePlan {
    struct Step {
        const TechniqueEntry* technique;
        TechniquePlan plan;
    };
    std::vector<Step> steps;  // every registered technique, in registry order, running or not
    // The frame's: the emitters' sampling and the dynamic grid, then each running technique's.
    ShaderFeatures features{};
    bool addsIndirect = false;   // a running technique writes the indirect term
    bool writesDisplay = false;  // a running technique writes the display image

    bool runs(std::string_view technique) const;
};

FramePlan planFrame(const lighting::LightingSettings& lighting, const SceneShape& scene,
                    glm::uvec2 size);

// The lighting as logs name it: the direct method, then " + " each term added to it
// ("restir biased area M=32 power bricks temporal spatial 5x30px + cache K=128 ...").
std::string describeLighting(const lighting::LightingSettings& lighting);

}  // namespace engine::render
