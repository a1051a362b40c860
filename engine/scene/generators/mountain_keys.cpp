// [[generator]] type = "mountain": keys of world/mountain_generator.h's massif.
#include "scene/generator_registry.h"
#include "world/mountain_generator.h"

namespace engine::scene {

namespace {

using world::MountainParams;

// snow_line and cliff_step: their default, 2^30 (what the writer writes), is above any world:
// no snow, no cliffs.
constexpr NumberRange kNoneAbove = wholeRange(-(1 << 30), 1 << 30, "voxels");

MountainParams parse(GeneratorKeys& g) {
    MountainParams p;
    world::ColumnMaterials& m = p.materials;
    m.top = g.material("top");
    m.soil = g.material("soil");
    m.rock = g.material("rock");
    m.soilDepth =
        g.integer("soil_depth", m.soilDepth, wholeRange(0, world::kMaxWorldExtent, "voxels"));
    m.snow = g.material("snow", "empty");
    m.snowLine = g.integer("snow_line", m.snowLine, kNoneAbove);
    m.cliff = g.material("cliff", "empty");
    m.cliffStep = g.integer("cliff_step", m.cliffStep, kNoneAbove);
    glm::vec3 size(g.scene().grid.sizeInVoxels());
    p.peak = g.vec2("peak", {size.x * 0.5f, size.z * 0.5f}, world::kCoordinateRange);
    p.peakHeight = static_cast<float>(
        g.number("peak_height", p.peakHeight,
                 closedRange(-world::kMaxWorldExtent, world::kMaxWorldExtent, "voxels")));
    p.baseHeight = static_cast<float>(
        g.number("base_height", p.baseHeight,
                 closedRange(-world::kMaxWorldExtent, world::kMaxWorldExtent, "voxels")));
    p.radius = static_cast<float>(g.number("radius", p.radius, aboveRange(0.0, 1e6, "voxels")));
    p.hills = static_cast<float>(g.number(
        "hills", p.hills, closedRange(-world::kMaxWorldExtent, world::kMaxWorldExtent, "voxels")));
    p.ridges = static_cast<float>(g.number("ridges", p.ridges, closedRange(0.0, 1.0)));
    p.wavelength =
        static_cast<float>(g.number("wavelength", p.wavelength, aboveRange(0.0, 1e6, "voxels")));
    p.octaves = g.integer("octaves", p.octaves, wholeRange(1, 12));
    p.terrace = g.integer("terrace", p.terrace, wholeRange(0, 64, "voxels"));
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed), kSeedRange));
    return p;
}

void write(const MountainParams& p, const GeneratorWriter& out) {
    const world::ColumnMaterials& m = p.materials;
    out.material("top", m.top);
    out.material("soil", m.soil);
    out.material("rock", m.rock);
    out.toml.key("soil_depth", m.soilDepth);
    out.material("snow", m.snow);
    out.toml.key("snow_line", m.snowLine);
    out.material("cliff", m.cliff);
    out.toml.key("cliff_step", m.cliffStep);
    out.toml.key("peak", p.peak);
    out.toml.key("peak_height", p.peakHeight);
    out.toml.key("base_height", p.baseHeight);
    out.toml.key("radius", p.radius);
    out.toml.key("hills", p.hills);
    out.toml.key("ridges", p.ridges);
    out.toml.key("wavelength", p.wavelength);
    out.toml.key("octaves", p.octaves);
    out.toml.key("terrace", p.terrace);
    out.toml.key("seed", p.seed);
}

}  // namespace

extern const GeneratorEntry kMountainGenerator =
    makeGeneratorEntry<MountainParams, parse,
                       generateOnGrid<MountainParams, world::generateMountain>, write>("mountain");

}  // namespace engine::scene
