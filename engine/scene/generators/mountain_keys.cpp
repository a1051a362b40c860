// [[generator]] type = "mountain": keys of world/mountain_generator.h's massif.
#include "scene/generator_registry.h"
#include "world/mountain_generator.h"

namespace engine::scene {

namespace {

using world::MountainParams;

MountainParams parse(GeneratorKeys& g) {
    MountainParams p;
    world::ColumnMaterials& m = p.materials;
    m.top = g.material("top");
    m.soil = g.material("soil");
    m.rock = g.material("rock");
    m.soilDepth = g.integer("soil_depth", m.soilDepth);
    m.snow = g.material("snow", "empty");
    m.snowLine = g.integer("snow_line", m.snowLine);
    m.cliff = g.material("cliff", "empty");
    m.cliffStep = g.integer("cliff_step", m.cliffStep);
    glm::vec3 size(g.scene().grid.sizeInVoxels());
    p.peak = g.vec2("peak", {size.x * 0.5f, size.z * 0.5f});
    p.peakHeight = static_cast<float>(g.number("peak_height", p.peakHeight));
    p.baseHeight = static_cast<float>(g.number("base_height", p.baseHeight));
    p.radius = static_cast<float>(g.number("radius", p.radius));
    p.hills = static_cast<float>(g.number("hills", p.hills));
    p.ridges = static_cast<float>(g.number("ridges", p.ridges));
    p.wavelength = static_cast<float>(g.number("wavelength", p.wavelength));
    p.octaves = g.integer("octaves", p.octaves);
    p.terrace = g.integer("terrace", p.terrace);
    p.seed = static_cast<std::uint32_t>(g.integer("seed", static_cast<int>(p.seed)));
    if (p.octaves < 1 || p.octaves > 12) g.fail(g.node("octaves"), "'octaves' must be in 1..12");
    if (p.radius <= 0.0f) g.fail(g.node("radius"), "'radius' must be positive");
    if (p.ridges < 0.0f || p.ridges > 1.0f) g.fail(g.node("ridges"), "'ridges' must be in 0..1");
    if (p.terrace < 0 || p.terrace > 64) g.fail(g.node("terrace"), "'terrace' must be in 0..64");
    if (m.soilDepth < 0) g.fail(g.node("soil_depth"), "'soil_depth' must not be negative");
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
