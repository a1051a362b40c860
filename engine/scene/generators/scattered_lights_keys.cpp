// [[generator]] type = "scattered_lights": keys of world/scattered_lights_generator.h.
#include "scene/generator_registry.h"
#include "world/scattered_lights_generator.h"

namespace engine::scene {

namespace {

using world::ScatteredLightsParams;

ScatteredLightsParams parse(GeneratorKeys& g) {
    ScatteredLightsParams p;
    p.spacing = g.integer("spacing", p.spacing);
    p.size = g.ivec3("size", p.size);
    p.margin = g.integer("margin", p.margin);
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
    p.light = g.material("light");
    if (p.spacing < 1 || p.spacing > 4096)
        g.fail(g.node("spacing"), "'spacing' must be in 1..4096");
    if (glm::any(glm::lessThan(p.size, glm::ivec3(1))) || p.size.x > p.spacing ||
        p.size.z > p.spacing || p.size.y > 256)
        g.fail(g.node("size"), "'size' must be at least 1, at most 'spacing' across and 256 high");
    if (p.margin < 0) g.fail(g.node("margin"), "'margin' must not be negative");
    return p;
}

void write(const ScatteredLightsParams& p, const GeneratorWriter& out) {
    out.toml.key("spacing", p.spacing);
    out.toml.key("size", p.size);
    out.toml.key("margin", p.margin);
    out.toml.key("seed", p.seed);
    out.material("light", p.light);
}

}  // namespace

extern const GeneratorEntry kScatteredLightsGenerator =
    makeGeneratorEntry<ScatteredLightsParams, parse,
                       generateOnGrid<ScatteredLightsParams, world::generateScatteredLights>,
                       write>("scattered_lights");

}  // namespace engine::scene
