// [[generator]] type = "terrain": keys of world/generators.h's height-field terrain.
#include "scene/generator_registry.h"
#include "world/generators.h"

namespace engine::scene {

namespace {

using world::TerrainParams;

TerrainParams parse(GeneratorKeys& g) {
    TerrainParams p;
    p.top = g.material("top");
    p.soil = g.material("soil");
    p.rock = g.material("rock");
    p.soilDepth = g.integer("soil_depth", p.soilDepth);
    p.baseHeight = static_cast<float>(g.number("base_height", p.baseHeight));
    p.amplitude = static_cast<float>(g.number("amplitude", p.amplitude));
    p.wavelength = static_cast<float>(g.number("wavelength", p.wavelength));
    p.octaves = g.integer("octaves", p.octaves);
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
    if (p.octaves < 1 || p.octaves > 12) g.fail(g.node("octaves"), "'octaves' must be in 1..12");
    return p;
}

void write(const TerrainParams& p, const GeneratorWriter& out) {
    out.material("top", p.top);
    out.material("soil", p.soil);
    out.material("rock", p.rock);
    out.toml.key("soil_depth", p.soilDepth);
    out.toml.key("base_height", p.baseHeight);
    out.toml.key("amplitude", p.amplitude);
    out.toml.key("wavelength", p.wavelength);
    out.toml.key("octaves", p.octaves);
    out.toml.key("seed", p.seed);
}

}  // namespace

extern const GeneratorEntry kTerrainGenerator =
    makeGeneratorEntry<TerrainParams, parse, generateOnGrid<TerrainParams, world::generateTerrain>,
                       write>("terrain");

}  // namespace engine::scene
