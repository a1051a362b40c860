// [[generator]] type = "text": keys of world/text_generator.h's built-in-font text.
#include "scene/generator_registry.h"
#include "world/text_generator.h"

namespace engine::scene {

namespace {

using world::TextParams;

TextParams parse(GeneratorKeys& g) {
    TextParams p;
    p.text = g.string("text");
    p.origin = g.ivec3("origin", {}, kVoxelIndexRange, true);
    p.right = g.ivec3("right", p.right, wholeRange(-1, 1));
    p.up = g.ivec3("up", p.up, wholeRange(-1, 1));
    p.scale = g.integer("scale", p.scale, wholeRange(1, 64, "voxels"));
    p.depth = g.integer("depth", p.depth, wholeRange(1, 64, "voxels"));
    p.spacing = g.integer("spacing", p.spacing, wholeRange(0, 64, "voxels"));
    p.material = g.material("material");
    if (std::string problem = world::validateTextParams(p); !problem.empty())
        g.fail(&g.raw(), "text: {}", problem);
    return p;
}

void write(const TextParams& p, const GeneratorWriter& out) {
    out.toml.key("text", p.text);
    out.toml.key("origin", p.origin);
    out.toml.key("right", p.right);
    out.toml.key("up", p.up);
    out.toml.key("scale", p.scale);
    out.toml.key("depth", p.depth);
    out.toml.key("spacing", p.spacing);
    out.material("material", p.material);
}

}  // namespace

extern const GeneratorEntry kTextGenerator =
    makeGeneratorEntry<TextParams, parse, generateOnGrid<TextParams, world::generateText>, write>(
        "text");

}  // namespace engine::scene
