// The techniques a frame can run, one line each (technique_registry.cpp), in the order their
// passes are recorded. Adding a technique: its folder pair (engine/render/<name>/,
// shaders/<name>/), its knob rows (lighting/lighting_knobs.cpp) and one line here.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "render/technique.h"

namespace engine::gpu {
class Context;
}

namespace engine::render {

struct TechniqueEntry {
    std::string_view name;
    TechniquePlan (*plan)(const lighting::LightingSettings&, const SceneShape&, glm::uvec2 size);
    std::string (*describe)(const lighting::LightingSettings&);
    std::unique_ptr<Technique> (*make)(gpu::Context&);
};

template <class T>
constexpr TechniqueEntry techniqueEntry(std::string_view name) {
    return {name, &T::plan, &T::describe, [](gpu::Context& ctx) -> std::unique_ptr<Technique> {
                return std::make_unique<T>(ctx);
            }};
}

std::span<const TechniqueEntry> techniqueRegistry();

}  // namespace engine::render
