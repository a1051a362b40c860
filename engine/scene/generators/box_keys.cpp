// [[generator]] type = "box": a filled (or hollow) box through world/world_edits.h.
#include "scene/generator_registry.h"
#include "world/world_edits.h"

namespace engine::scene {

namespace {

struct BoxParams {
    world::Box box;
    world::MaterialId material = world::kEmpty;
    int hollowWall = 0;  // 0 = solid
};

BoxParams parse(GeneratorKeys& g) {
    BoxParams p;
    p.box = world::Box{g.ivec3("min", {}, kVoxelIndexRange, true),
                       g.ivec3("max", {}, kVoxelIndexRange, true)};
    p.material = g.material("material");
    p.hollowWall = g.integer("hollow_wall", 0, wholeRange(0, world::kMaxWorldExtent, "voxels"));
    return p;
}

Status run(const BoxParams& p, world::Scene& scene) {
    world::fillBox(scene.grid, p.box, p.material);
    if (p.hollowWall > 0)
        world::fillBox(scene.grid, world::Box{p.box.min + p.hollowWall, p.box.max - p.hollowWall},
                       world::kEmpty);
    return {};
}

void write(const BoxParams& p, const GeneratorWriter& out) {
    out.toml.key("min", p.box.min);
    out.toml.key("max", p.box.max);
    out.material("material", p.material);
    if (p.hollowWall != 0) out.toml.key("hollow_wall", p.hollowWall);
}

}  // namespace

extern const GeneratorEntry kBoxGenerator = makeGeneratorEntry<BoxParams, parse, run, write>("box");

}  // namespace engine::scene
