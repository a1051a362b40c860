// [[generator]] type = "cornell": keys of world/generators.h's Cornell box (thesis §3.2).
#include "scene/generator_registry.h"
#include "world/generators.h"

namespace engine::scene {

namespace {

using world::CornellParams;

CornellParams parse(GeneratorKeys& g) {
    CornellParams p;
    p.origin = g.ivec3("origin", p.origin, kVoxelIndexRange);
    p.interior =
        g.integer("interior", p.interior, wholeRange(16, world::kMaxWorldExtent, "voxels"));
    p.wall = g.integer("wall", p.wall, wholeRange(0, 1024, "voxels"));
    p.lightBricks = g.integer("light_bricks", p.lightBricks, wholeRange(0, 4096, "bricks"));
    p.white = g.material("white");
    p.red = g.material("red");
    p.green = g.material("green");
    p.light = g.material("light");
    if (p.interior < 16 || p.interior % 8)
        g.fail(g.node("interior"), "'interior' must be a multiple of 8, >= 16");
    if (p.lightBricks * 8 > p.interior)
        g.fail(g.node("light_bricks"), "the light is wider than the box");
    return p;
}

void write(const CornellParams& p, const GeneratorWriter& out) {
    out.toml.key("origin", p.origin);
    out.toml.key("interior", p.interior);
    out.toml.key("wall", p.wall);
    out.toml.key("light_bricks", p.lightBricks);
    out.material("white", p.white);
    out.material("red", p.red);
    out.material("green", p.green);
    out.material("light", p.light);
}

}  // namespace

extern const GeneratorEntry kCornellGenerator =
    makeGeneratorEntry<CornellParams, parse,
                       generateOnGrid<CornellParams, world::generateCornellBox>, write>("cornell");

}  // namespace engine::scene
