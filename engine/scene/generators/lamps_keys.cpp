// [[generator]] type = "lamps": keys of world/generators.h's lamp posts.
#include "scene/generator_registry.h"
#include "world/generators.h"

namespace engine::scene {

namespace {

using world::LampsParams;

LampsParams parse(GeneratorKeys& g) {
    LampsParams p;
    p.count = g.integer("count", p.count);
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
    p.postHeight = g.integer("post_height", p.postHeight);
    p.lampSize = g.integer("lamp_size", p.lampSize);
    p.post = g.material("post");
    p.light = g.material("light");
    if (p.count < 0 || p.count > 1000000) g.fail(g.node("count"), "'count' must be in 0..1000000");
    if (p.lampSize < 1 || p.lampSize > 64)
        g.fail(g.node("lamp_size"), "'lamp_size' must be in 1..64");
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
