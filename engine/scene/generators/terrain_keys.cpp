// [[generator]] type = "terrain": keys of world/generators.h's height-field terrain.
#include "scene/generator_registry.h"
#include "world/generators.h"
#include "world/world_limits.h"

namespace engine::scene {

namespace {

using world::TerrainParams;

TerrainParams parse(GeneratorKeys& g) {
    TerrainParams p;
    p.top = g.material("top");
    p.soil = g.material("soil");
    p.rock = g.material("rock");
    p.soilDepth =
        g.integer("soil_depth", p.soilDepth, wholeRange(0, world::kMaxWorldExtent, "voxels"));
    p.baseHeight = static_cast<float>(
        g.number("base_height", p.baseHeight,
                 closedRange(-world::kMaxWorldExtent, world::kMaxWorldExtent, "voxels")));
    p.amplitude = static_cast<float>(
        g.number("amplitude", p.amplitude,
                 closedRange(-world::kMaxWorldExtent, world::kMaxWorldExtent, "voxels")));
    p.wavelength =
        static_cast<float>(g.number("wavelength", p.wavelength, aboveRange(0.0, 1e6, "voxels")));
    p.octaves = g.integer("octaves", p.octaves, wholeRange(1, 12));
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed), kSeedRange));
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
