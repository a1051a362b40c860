// [[generator]] type = "lamps": keys of world/generators.h's lamp posts.
#include "scene/generator_registry.h"
#include "world/generators.h"

namespace engine::scene {

namespace {

using world::LampsParams;

LampsParams parse(GeneratorKeys& g) {
    LampsParams p;
    p.count = g.integer("count", p.count, wholeRange(0, 1000000));
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed), kSeedRange));
    p.postHeight = g.integer("post_height", p.postHeight, wholeRange(0, 4096, "voxels"));
    p.lampSize = g.integer("lamp_size", p.lampSize, wholeRange(1, 64, "voxels"));
    p.post = g.material("post");
    p.light = g.material("light");
    return p;
}

void write(const LampsParams& p, const GeneratorWriter& out) {
    out.toml.key("count", p.count);
    out.toml.key("seed", p.seed);
    out.toml.key("post_height", p.postHeight);
    out.toml.key("lamp_size", p.lampSize);
    out.material("post", p.post);
    out.material("light", p.light);
}

}  // namespace

extern const GeneratorEntry kLampsGenerator =
    makeGeneratorEntry<LampsParams, parse, generateOnGrid<LampsParams, world::generateLamps>,
                       write>("lamps");

}  // namespace engine::scene
