// [[generator]] type = "buildings": keys of world/generators.h's hollow buildings.
#include "scene/generator_registry.h"
#include "world/generators.h"

namespace engine::scene {

namespace {

using world::BuildingsParams;

BuildingsParams parse(GeneratorKeys& g) {
    BuildingsParams p;
    p.count = g.integer("count", p.count, wholeRange(0, 10000));
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed), kSeedRange));
    p.minHeight =
        g.integer("min_height", p.minHeight, wholeRange(6, world::kMaxWorldExtent, "voxels"));
    p.maxHeight =
        g.integer("max_height", p.maxHeight, wholeRange(6, world::kMaxWorldExtent, "voxels"));
    // Sizes are [x, y, z] like every extent; y is not used.
    glm::ivec3 minSize = g.ivec3("min_size", {p.minSize.x, 0, p.minSize.y},
                                 wholeRange(0, world::kMaxWorldExtent, "voxels"));
    glm::ivec3 maxSize = g.ivec3("max_size", {p.maxSize.x, 0, p.maxSize.y},
                                 wholeRange(0, world::kMaxWorldExtent, "voxels"));
    p.minSize = {minSize.x, minSize.z};
    p.maxSize = {maxSize.x, maxSize.z};
    p.wall = g.material("wall");
    p.roof = g.material("roof");
    p.window = g.material("window");
    if (glm::any(glm::lessThan(p.minSize, glm::ivec2(4))) ||
        glm::any(glm::lessThan(p.maxSize, p.minSize)) || p.minHeight < 6 ||
        p.maxHeight < p.minHeight)
        g.fail(&g.raw(),
               "buildings: sizes must satisfy 4 <= min_size <= max_size and 6 <= min_height <= "
               "max_height");
    return p;
}

void write(const BuildingsParams& p, const GeneratorWriter& out) {
    out.toml.key("count", p.count);
    out.toml.key("seed", p.seed);
    out.toml.key("min_size", glm::ivec3(p.minSize.x, 0, p.minSize.y));
    out.toml.key("max_size", glm::ivec3(p.maxSize.x, 0, p.maxSize.y));
    out.toml.key("min_height", p.minHeight);
    out.toml.key("max_height", p.maxHeight);
    out.material("wall", p.wall);
    out.material("roof", p.roof);
    out.material("window", p.window);
}

}  // namespace

extern const GeneratorEntry kBuildingsGenerator =
    makeGeneratorEntry<BuildingsParams, parse,
                       generateOnGrid<BuildingsParams, world::generateBuildings>, write>(
        "buildings");

}  // namespace engine::scene
