// [[generator]] type = "scattered_lights": keys of world/scattered_lights_generator.h.
#include "scene/generator_registry.h"
#include "world/scattered_lights_generator.h"

namespace engine::scene {

namespace {

using world::ScatteredLightsParams;

ScatteredLightsParams parse(GeneratorKeys& g) {
    ScatteredLightsParams p;
    p.spacing = g.integer("spacing", p.spacing, wholeRange(1, 4096, "voxels"));
    p.size = g.ivec3("size", p.size, wholeRange(1, 4096, "voxels"));
    p.margin = g.integer("margin", p.margin, wholeRange(0, world::kMaxWorldExtent, "voxels"));
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed), kSeedRange));
    p.light = g.material("light");
    if (glm::any(glm::lessThan(p.size, glm::ivec3(1))) || p.size.x > p.spacing ||
        p.size.z > p.spacing || p.size.y > 256)
        g.fail(g.node("size"), "'size' must be at least 1, at most 'spacing' across and 256 high");
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
