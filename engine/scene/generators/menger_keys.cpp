// [[generator]] type = "menger": keys of world/menger_generator.h's sponge.
#include "scene/generator_registry.h"
#include "world/menger_generator.h"

namespace engine::scene {

namespace {

using world::MengerParams;

MengerParams parse(GeneratorKeys& g) {
    MengerParams p;
    p.origin = g.ivec3("origin", p.origin, kVoxelIndexRange);
    p.level = g.integer("level", p.level, wholeRange(0, 6));
    p.scale = g.integer("scale", p.scale, wholeRange(1, 64, "voxels"));
    p.material = g.material("material");
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
