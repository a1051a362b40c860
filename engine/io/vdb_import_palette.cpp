// The palette of an OpenVDB import: the materials a material rule needs (one, height bands, our
// own file's palette, one per distinct id, or colours quantised from the source), and their ids
// in the scene they are imported into (io/vdb_import_state.h).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "io/vdb_import_state.h"
#include "world/world_limits.h"

namespace engine::io::vdb_import {

namespace vdb = openvdb;

namespace {

glm::vec3 idColour(std::int64_t v) {
    // Distinct, pleasant colours for foreign ids: golden-ratio hue steps, fixed saturation/value.
    double h = std::fmod(double(v) * 0.61803398875 + 0.1, 1.0);
    if (h < 0) h += 1.0;
    glm::vec3 rgb = glm::clamp(
        glm::abs(glm::mod(glm::vec3(float(h) * 6.0f) + glm::vec3(0, 4, 2), 6.0f) - 3.0f) - 1.0f,
        0.0f, 1.0f);
    return glm::mix(glm::vec3(1.0f), rgb, 0.55f) * 0.8f;
}

std::vector<world::Material> defaultHeightMaterials() {
    return {{"height_0", {0.30f, 0.24f, 0.18f}, glm::vec3(0.0f), 0.0f},
            {"height_1", {0.25f, 0.42f, 0.16f}, glm::vec3(0.0f), 0.0f},
            {"height_2", {0.45f, 0.45f, 0.47f}, glm::vec3(0.0f), 0.0f},
            {"height_3", {0.90f, 0.90f, 0.92f}, glm::vec3(0.0f), 0.0f}};
}

// Every solid value of the shape grid inside the source box: each tile once with the voxels it
// covers, each active leaf voxel once. Streamed when the import streams, else read in pieces.
Status forEachSourceValue(ImportState& im,
                          const std::function<Status(const Sample&, std::uint64_t voxels)>& f) {
    const Box& sourceBox = im.place.sourceBox;
    auto tile = [&](const Box& b, const Sample& s) { return f(s, volume(b.intersect(sourceBox))); };
    auto voxel = [&](const Sample& s) { return f(s, 1); };
    if (im.streaming) {
        return streamSource(
            im, tile, [&](const vdb::Coord& origin, const Sample* samples) -> Status {
                // OpenVDB's leaf order: z fastest.
                for (int i = 0; i < 512; ++i) {
                    if (!samples[i].active) continue;
                    const glm::ivec3 p(origin.x() + (i >> 6), origin.y() + ((i >> 3) & 7),
                                       origin.z() + (i & 7));
                    if (!sourceBox.contains(p)) continue;
                    if (Status s = voxel(samples[i]); !s) return s;
                }
                return {};
            });
    }
    auto topology = makeSource(*im.grids.shapeHeader);
    topology->attach(im.reader.readTopology(im.grids.shapeIndex));
    Status tiles = forEachSolidTile(im, *topology, tile);
    topology.reset();
    if (!tiles) return tiles;
    return scanActiveVoxels(im, im.grids.shapeIndex, im.topology.leaves, sourceBox, voxel);
}

// One material per distinct value, in increasing order.
Status addIdMaterials(ImportState& im) {
    std::vector<std::int64_t> values;
    std::unordered_map<std::int64_t, int> seen;
    Status scanned = forEachSourceValue(im, [&](const Sample& s, std::uint64_t) -> Status {
        const std::int64_t v = std::int64_t(s.scalar);
        if (!seen.emplace(v, 0).second) return {};
        values.push_back(v);
        if (values.size() >= world::kMaxMaterials)
            return makeError("{}: grid '{}' holds more than {} distinct ids", im.file, im.plan.grid,
                             world::kMaxMaterials - 1);
        return {};
    });
    if (!scanned) return scanned;
    std::sort(values.begin(), values.end());
    ImportPalette& palette = im.palette;
    for (std::int64_t v : values) {
        palette.idLut[v] = int(palette.materials.size());
        palette.materials.push_back({fmt::format("id_{}", v), idColour(v), glm::vec3(0.0f), 0.0f});
    }
    return {};
}

// Colours of the colour grid (or of a vec3 shape grid) quantised to at most maxColours.
Status addColourMaterials(ImportState& im) {
    ColourHistogram histogram;
    Status scanned;
    if (im.grids.colourIndex >= 0) {
        // The colour grid's voxels over the imported region (through world space).
        scanned = scanActiveVoxels(im, std::size_t(im.grids.colourIndex), im.topology.colourLeaves,
                                   colourRegion(im, im.place.sourceBox), [&](const Sample& s) {
                                       histogram.add(s.colour);
                                       return Status{};
                                   });
    } else {
        scanned = forEachSourceValue(im, [&](const Sample& s, std::uint64_t voxels) {
            histogram.add(s.colour, voxels);
            return Status{};
        });
    }
    if (!scanned) return scanned;
    std::vector<glm::vec3> colours = quantizeColours(histogram, im.options.maxColours);
    if (colours.empty()) colours.push_back(glm::vec3(0.7f));
    for (std::size_t i = 0; i < colours.size(); ++i)
        im.palette.materials.push_back(
            {fmt::format("colour_{:02}", i + 1), colours[i], glm::vec3(0.0f), 0.0f});
    im.palette.mapper = std::make_unique<ColourMapper>(colours);
    im.report.colours = int(colours.size());
    return {};
}

}  // namespace

Status buildPalette(ImportState& im) {
    std::vector<world::Material>& materials = im.palette.materials;
    materials.assign(1, world::Material{});
    switch (im.grids.rule) {
        case MaterialRule::Constant:
            materials.push_back(im.options.material);
            return {};
        case MaterialRule::Height: {
            auto bands = im.options.heightMaterials.empty() ? defaultHeightMaterials()
                                                            : im.options.heightMaterials;
            materials.insert(materials.end(), bands.begin(), bands.end());
            return {};
        }
        case MaterialRule::Ids:
            if (im.grids.kind == Kind::VoxIds) {
                const auto& own = im.grids.worldHeader.palette.materials();
                materials.insert(materials.end(), own.begin() + 1, own.end());
                return {};
            }
            return addIdMaterials(im);
        case MaterialRule::Colour:
            return addColourMaterials(im);
        default:
            return {};
    }
}

Status addToScenePalette(ImportState& im, world::Scene& scene, bool intoExisting) {
    // Appended in order for a new world (so ids stay exactly as in our own files), merged by name
    // into an existing one.
    const std::vector<world::Material>& materials = im.palette.materials;
    std::vector<world::MaterialId>& remap = im.palette.remap;
    remap.assign(materials.size(), world::kEmpty);
    for (std::size_t i = 1; i < materials.size(); ++i) {
        std::optional<world::MaterialId> id;
        if (intoExisting) id = scene.palette.find(materials[i].name);
        if (!id) id = scene.palette.add(materials[i]);
        if (!id)
            return makeError("{}: the palette is full ({} materials)", im.file,
                             world::kMaxMaterials - 1);
        remap[i] = *id;
    }
    im.report.materials = materials.size() - 1;
    return {};
}

}  // namespace engine::io::vdb_import
