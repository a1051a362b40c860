// [[generator]] type = "menger": keys of world/menger_generator.h's sponge.
#include "scene/generator_registry.h"
#include "world/menger_generator.h"

namespace engine::scene {

namespace {

using world::MengerParams;

MengerParams parse(GeneratorKeys& g) {
    MengerParams p;
    p.origin = g.ivec3("origin", p.origin);
    p.level = g.integer("level", p.level);
    p.scale = g.integer("scale", p.scale);
    p.material = g.material("material");
    if (p.level < 0 || p.level > 6) g.fail(g.node("level"), "'level' must be in 0..6");
    if (p.scale < 1 || p.scale > 64) g.fail(g.node("scale"), "'scale' must be in 1..64");
    return p;
}

void write(const MengerParams& p, const GeneratorWriter& out) {
    out.toml.key("origin", p.origin);
    out.toml.key("level", p.level);
    out.toml.key("scale", p.scale);
    out.material("material", p.material);
}

}  // namespace

extern const GeneratorEntry kMengerGenerator =
    makeGeneratorEntry<MengerParams, parse, generateOnGrid<MengerParams, world::generateMenger>,
                       write>("menger");

}  // namespace engine::scene
