// [[generator]] type = "apartment": keys of world/apartment_generator.h's apartment block.
#include "scene/generator_registry.h"
#include "world/apartment_generator.h"

namespace engine::scene {

namespace {

using world::ApartmentParams;

ApartmentParams parse(GeneratorKeys& g) {
    ApartmentParams p;
    p.min = g.ivec3("min", {}, kVoxelIndexRange, true);
    p.size = g.ivec3("size", {}, wholeRange(1, world::kMaxWorldExtent, "voxels"), true);
    p.storey = g.integer("storey", p.storey, wholeRange(6, 64, "voxels"));
    p.windowSize = g.ivec2("window_size", p.windowSize, wholeRange(1, 1024, "voxels"));
    p.windowSpacing = g.integer("window_spacing", p.windowSpacing, wholeRange(2, 1024, "voxels"));
    p.lit = static_cast<float>(g.number("lit", p.lit, closedRange(0.0, 1.0)));
    p.balconies = static_cast<float>(g.number("balconies", p.balconies, closedRange(0.0, 1.0)));
    p.baseDepth =
        g.integer("base_depth", p.baseDepth, wholeRange(0, world::kMaxWorldExtent, "voxels"));
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed), kSeedRange));
    p.wall = g.material("wall");
    p.slab = g.material("slab");
    p.railing = g.material("railing", "empty");
    p.base = g.material("base", "empty");
    p.cornerLight = g.material("corner_light", "empty");
    for (const std::string& name : g.strings("windows")) {
        auto id = g.scene().palette.find(name);
        if (!id) g.fail(g.node("windows"), "unknown material '{}'", name);
        p.windowLights.push_back(*id);
    }
    if (p.size.x < 8 || p.size.z < 8 || p.size.y < p.storey + 1)
        g.fail(g.node("size"),
               "'size' must be at least 8 across and one storey ('storey' + 1) high");
    if (p.windowSize.x < 1 || p.windowSize.y < 1 || p.windowSpacing <= p.windowSize.x)
        g.fail(g.node("window_size"),
               "windows must be at least 1x1 and narrower than 'window_spacing'");
    return p;
}

void write(const ApartmentParams& p, const GeneratorWriter& out) {
    out.toml.key("min", p.min);
    out.toml.key("size", p.size);
    out.toml.key("storey", p.storey);
    out.toml.key("window_size", p.windowSize);
    out.toml.key("window_spacing", p.windowSpacing);
    out.toml.key("lit", p.lit);
    out.toml.key("balconies", p.balconies);
    out.toml.key("base_depth", p.baseDepth);
    out.toml.key("seed", p.seed);
    out.material("wall", p.wall);
    out.material("slab", p.slab);
    out.material("railing", p.railing);
    out.material("base", p.base);
    out.material("corner_light", p.cornerLight);
    std::vector<std::string> windows;
    for (world::MaterialId id : p.windowLights) windows.push_back(out.palette[id].name);
    if (!windows.empty()) out.toml.key("windows", windows);
}

}  // namespace

extern const GeneratorEntry kApartmentGenerator =
    makeGeneratorEntry<ApartmentParams, parse,
                       generateOnGrid<ApartmentParams, world::generateApartment>, write>(
        "apartment");

}  // namespace engine::scene
