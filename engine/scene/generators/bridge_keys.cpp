// [[generator]] type = "bridge": keys of world/bridge_generator.h's bridge deck.
#include "scene/generator_registry.h"
#include "world/bridge_generator.h"

namespace engine::scene {

namespace {

using world::BridgeParams;

BridgeParams parse(GeneratorKeys& g) {
    BridgeParams p;
    p.min = g.ivec3("min", {}, kVoxelIndexRange, true);
    p.max = g.ivec3("max", {}, kVoxelIndexRange, true);
    p.railingHeight = g.integer("railing_height", p.railingHeight, wholeRange(0, 64, "voxels"));
    p.postSpacing = g.integer("post_spacing", p.postSpacing, wholeRange(1, 4096, "voxels"));
    p.lightSpacing = g.integer("light_spacing", p.lightSpacing, wholeRange(0, 4096, "voxels"));
    p.deck = g.material("deck");
    p.railing = g.material("railing", "empty");
    p.light = g.material("light", "empty");
    if (world::Box{p.min, p.max}.empty())
        g.fail(g.node("max"), "'max' must exceed 'min' on every axis");
    if (p.postSpacing < 1) g.fail(g.node("post_spacing"), "'post_spacing' must be positive");
    if (p.lightSpacing < 0) g.fail(g.node("light_spacing"), "'light_spacing' must not be negative");
    if (p.railingHeight < 0 || p.railingHeight > 64)
        g.fail(g.node("railing_height"), "'railing_height' must be in 0..64");
    return p;
}

void write(const BridgeParams& p, const GeneratorWriter& out) {
    out.toml.key("min", p.min);
    out.toml.key("max", p.max);
    out.toml.key("railing_height", p.railingHeight);
    out.toml.key("post_spacing", p.postSpacing);
    out.toml.key("light_spacing", p.lightSpacing);
    out.material("deck", p.deck);
    out.material("railing", p.railing);
    out.material("light", p.light);
}

}  // namespace

extern const GeneratorEntry kBridgeGenerator =
    makeGeneratorEntry<BridgeParams, parse, generateOnGrid<BridgeParams, world::generateBridge>,
                       write>("bridge");

}  // namespace engine::scene
