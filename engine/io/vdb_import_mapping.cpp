// Source values to voxels for an OpenVDB import: which samples are solid for the grid's kind,
// how a world voxel samples a resampled grid, and which material a solid voxel gets under the
// material rule (io/vdb_import_state.h).
#include <algorithm>

#include "io/vdb_import_state.h"
#include "world/world_limits.h"

namespace engine::io::vdb_import {

namespace vdb = openvdb;

namespace {

int heightBand(const ImportState& im, int y) {
    const Box& worldBox = im.place.worldBox;
    const int bands = im.grids.heightBands;
    int span = std::max(1, worldBox.max.y - worldBox.min.y);
    return std::clamp(int(std::int64_t(y - worldBox.min.y) * bands / span), 0, bands - 1);
}

int colourMaterial(ImportState& im, glm::vec3 colour, std::uint64_t voxels = 1) {
    ColourMapper& mapper = *im.palette.mapper;  // nearest() memoises
    int index = mapper.nearest(colour);
    im.palette.colourError.add(
        double(glm::length(clampAlbedo(colour) - mapper.palette()[std::size_t(index)])), voxels);
    return 1 + index;
}

// The colour grid's value at world voxel t's centre (through world space when the grids'
// transforms differ).
glm::vec3 colourAt(const ImportState& im, glm::ivec3 t) {
    const AxisMap& map = im.place.map;
    glm::dvec3 x = map.toSourceCentre(map.centre(t));
    vdb::Vec3d ijk(x.x, x.y, x.z);
    if (!im.grids.sameXform)
        ijk = im.grids.colourXform->worldToIndex(im.grids.shapeXform->indexToWorld(ijk));
    return im.colour->at(vdb::Coord::round(ijk)).colour;
}

}  // namespace

bool isSolid(const ImportState& im, const Sample& s) {
    switch (im.grids.kind) {
        case Kind::LevelSet:
            return s.scalar < 0.0;
        case Kind::Fog:
            if (s.active) im.largestFogValue = std::max(im.largestFogValue, s.scalar);
            return s.active && s.scalar >= double(im.options.fogThreshold);
        default:
            return s.active;
    }
}

bool solidAt(const ImportState& im, glm::ivec3 t, Sample& s) {
    const Placement& place = im.place;
    const AxisMap& map = place.map;
    const SourceGrid& shape = *im.shape;
    auto inside = [&](glm::ivec3 i) { return place.sourceBox.contains(i); };
    auto coord = [](glm::ivec3 i) { return vdb::Coord(i.x, i.y, i.z); };
    if (place.trilinear) {
        glm::dvec3 x = map.toSourceCentre(map.centre(t));
        if (!inside(glm::ivec3(glm::round(x)))) return false;
        s.scalar = shape.trilinear(vdb::Vec3d(x.x, x.y, x.z));
        return s.scalar < 0.0;
    }
    if (place.footprint) {
        glm::ivec3 lo, hi;
        map.footprint(t, lo, hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    glm::ivec3 i = map.toSource({x, y, z});
                    if (!inside(i)) continue;
                    s = shape.at(coord(i));
                    if (s.scalar < 0.0) return true;
                }
        return false;
    }
    glm::ivec3 i = map.toSource(map.nearest(t));
    if (!inside(i)) return false;
    s = shape.at(coord(i));
    return isSolid(im, s);
}

Result<int> materialFor(ImportState& im, glm::ivec3 t, const Sample& s) {
    const ChosenGrids& g = im.grids;
    switch (g.rule) {
        case MaterialRule::Constant:
            return 1;
        case MaterialRule::Height:
            return 1 + heightBand(im, t.y);
        case MaterialRule::Colour:
            return colourMaterial(im, g.colourIndex >= 0 ? colourAt(im, t) : s.colour);
        case MaterialRule::Ids: {
            const std::int64_t v = std::int64_t(s.scalar);
            const std::size_t materials = im.palette.materials.size();
            if (g.kind == Kind::VoxIds) {
                if (v < 1 || std::uint64_t(v) >= materials)
                    return makeError(
                        "{}: corrupt voxengine file: material id {} outside the palette of {}",
                        im.file, v, materials - 1);
                return int(v);
            }
            auto it = im.palette.idLut.find(v);
            if (it == im.palette.idLut.end())
                return makeError("{}: id {} was not seen while scanning the grid", im.file, v);
            return it->second;
        }
        default:
            return 1;
    }
}

Result<int> uniformMaterial(ImportState& im, const Sample& tile, const Box& cellBox) {
    switch (im.grids.rule) {
        case MaterialRule::Constant:
            return 1;
        case MaterialRule::Height: {
            int lo = heightBand(im, cellBox.min.y), hi = heightBand(im, cellBox.max.y - 1);
            return lo == hi ? 1 + lo : kVariesInCell;
        }
        case MaterialRule::Colour:
            if (im.grids.colourIndex >= 0)
                return kVariesInCell;  // colours come from another grid: read them
            return im.palette.mapper ? colourMaterial(im, tile.colour, world::kBrickVoxels) : 0;
        case MaterialRule::Ids:
            if (im.palette.materials.empty()) return 0;
            return materialFor(im, cellBox.min, tile);
        default:
            return kVariesInCell;
    }
}

}  // namespace engine::io::vdb_import
