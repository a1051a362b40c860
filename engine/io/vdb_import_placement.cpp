// Placing an OpenVDB import: which way is up, how many world voxels per source voxel, and where
// the source lands in the world (io/vdb_import_placement.h).
#include "io/vdb_import_placement.h"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <fmt/format.h>

#include "core/number_check.h"
#include "core/quoted_string.h"
#include "io/vdb_import_state.h"
#include "world/scene.h"
#include "world/world_limits.h"

namespace engine::io::vdb_import {

namespace vdb = openvdb;

vdb::CoordBBox leafAligned(const Box& b) {
    auto down = [](int v) { return v >= 0 ? v & ~7 : -((-v + 7) & ~7); };
    glm::ivec3 lo(down(b.min.x), down(b.min.y), down(b.min.z));
    glm::ivec3 hi(down(b.max.x + 7), down(b.max.y + 7), down(b.max.z + 7));
    return vdb::CoordBBox(vdb::Coord(lo.x, lo.y, lo.z), vdb::Coord(hi.x - 1, hi.y - 1, hi.z - 1));
}

Box cropBox(const VdbImportOptions& options) {
    return options.crop ? *options.crop : Box{glm::ivec3(INT32_MIN / 2), glm::ivec3(INT32_MAX / 2)};
}

Box unite(const Box& a, const Box& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

std::uint64_t volume(const Box& b) {
    if (b.empty()) return 0;
    glm::u64vec3 s(b.size());
    return s.x * s.y * s.z;
}

namespace {

std::string metaString(const vdb::MetaMap& m, const char* key) {
    auto s = vdb::DynamicPtrCast<const vdb::StringMetadata>(m[key]);
    return s ? s->value() : std::string();
}

// Why a file counts as Blender's (Z-up), or empty. Blender marks its files in several ways over
// its versions, and Blender 2.8+ fluid caches (written by Mantaflow) not at all with `creator`:
//  - `creator` naming Blender (file or grid), as its 2.7x smoke caches write;
//  - file metadata under "blender/" (2.7x smoke caches: blender/smoke/resolution, ...);
//  - Mantaflow's per-grid metadata `file_base_resolution` and `file_voxel_size` (2.8x-3.x caches);
//  - Mantaflow's smoke grid names: a `density` grid beside `shadow`, `react` or `color_r`, which
//    only Blender's smoke caches write (Houdini and EmberGen name theirs density, temperature,
//    flame(s), fuel, vel).
std::string blenderEvidence(ImportState& im) {
    const vdb::MetaMap& file = im.reader.fileMetadata();
    const vdb::GridBase& shape = *im.grids.shapeHeader;
    for (const char* where : {"file", "grid"}) {
        const std::string creator = metaString(where[0] == 'f' ? file : shape, "creator");
        if (creator.find("Blender") != std::string::npos)
            return fmt::format("its {} creator is '{}'", where, printableText(creator));
    }
    for (auto it = file.beginMeta(); it != file.endMeta(); ++it)
        if (it->first.rfind("blender/", 0) == 0)
            return fmt::format("it has Blender's metadata '{}'", printableText(it->first));
    for (const char* key : {"file_base_resolution", "file_voxel_size"})
        if (shape[key])
            return fmt::format("it has Mantaflow's metadata '{}' (Blender's fluid cache)", key);
    bool density = false;
    std::string smokeGrid;
    for (const VdbReader::Entry& e : im.reader.grids()) {
        density |= e.name == "density";
        if (e.name == "shadow" || e.name == "react" || e.name == "color_r") smokeGrid = e.name;
    }
    if (density && !smokeGrid.empty())
        return fmt::format("its grids 'density' and '{}' are Blender's smoke cache's", smokeGrid);
    return {};
}

}  // namespace

Status orientAndScale(ImportState& im) {
    const VdbImportOptions& o = im.options;
    const ChosenGrids& g = im.grids;
    AxisMap& map = im.place.map;
    bool upZ = o.up == UpAxis::Z;
    std::string blender;
    if (o.up == UpAxis::Auto && !g.voxengine) {
        blender = blenderEvidence(im);
        upZ = !blender.empty();
    }
    im.plan.upZ = upZ;
    if (upZ) {
        // Z-up to Y-up, a rotation about x: (x, y, z) -> (x, z, -y).
        map.perm[0] = 0, map.perm[1] = 2, map.perm[2] = 1;
        map.sign[0] = 1, map.sign[1] = 1, map.sign[2] = -1;
        if (o.up == UpAxis::Auto)
            im.plan.notes.push_back(
                fmt::format("Z-up: written by Blender ({}); --up y to keep its axes", blender));
    }

    vdb::Vec3d vs = g.shapeXform->voxelSize();
    im.plan.sourceVoxelSize = glm::dvec3(vs.x(), vs.y(), vs.z());
    double smallest = std::min({vs.x(), vs.y(), vs.z()});
    double target = o.voxelSize > 0.0 ? o.voxelSize : smallest;
    if (g.voxengine && o.voxelSize <= 0.0) target = vs.x();
    im.plan.voxelSize = target;
    bool uniform = std::abs(vs.x() - vs.y()) <= 1e-6 * smallest &&
                   std::abs(vs.x() - vs.z()) <= 1e-6 * smallest;
    if (!uniform && o.voxelSize <= 0.0)
        im.plan.notes.push_back(
            fmt::format("voxels are {:.4g} x {:.4g} x {:.4g}: resampled to a uniform {:.4g}",
                        vs.x(), vs.y(), vs.z(), target));
    for (int a = 0; a < 3; ++a) {
        double s = vs[map.perm[a]] / target;
        if (std::abs(s - 1.0) < 1e-9) s = 1.0;
        if (!(s >= 1.0 / 64.0 && s <= 64.0))
            return makeError(
                "{}: resampling by {:.4g}x on an axis is outside 1/64..64 (voxel size {:.4g} to "
                "{:.4g})",
                im.file, s, vs[map.perm[a]], target);
        map.scale[a] = s;
    }
    im.plan.scale = map.scale;
    // It becomes the world's voxel_size, a float: the scene key's check, on the value the world
    // keeps (a size too small for a float would be kept as 0).
    const std::string what = o.voxelSize > 0.0 ? std::string("--voxel-size")
                                               : fmt::format("grid '{}' voxel size", im.plan.grid);
    Status kept = checkNumber(what, target, world::kVoxelSizeRange);
    if (kept && !(float(target) > 0.0f))
        kept = makeError("{} {:g} is below the smallest a world holds ({:g})", what, target,
                         double(FLT_MIN));
    if (!kept) return makeError("{}: {}", im.file, kept.error().message);
    const bool unitScale = map.scale == glm::dvec3(1.0);
    if (g.kind == Kind::LevelSet && !unitScale) {
        im.place.trilinear = glm::all(glm::greaterThanEqual(map.scale, glm::dvec3(1.0)));
        im.place.footprint = !im.place.trilinear;
        im.plan.notes.push_back(
            im.place.trilinear
                ? "level set resampled finer: inside where the trilinear distance < 0"
                : "level set resampled coarser: conservative (solid if any source voxel in it is)");
    }
    return {};
}

Status placeOffset(ImportState& im, const world::Scene* target) {
    const VdbImportOptions& o = im.options;
    const ChosenGrids& g = im.grids;
    Placement& place = im.place;
    AxisMap& map = place.map;
    const bool upZ = im.plan.upZ;
    const bool unitScale = map.scale == glm::dvec3(1.0);

    Box oriented = map.orient(place.sourceBox);
    if (o.offset) {
        map.offset = glm::dvec3(*o.offset);
    } else if (g.voxengine && unitScale && !upZ && !o.crop) {
        map.offset = glm::dvec3(0.0);  // our own files keep their coordinates
    } else if (unitScale) {
        // Smallest offset that lands everything at >= 0 with source leaves on our cells, so the
        // source's tiles and leaves map one to one onto homogeneous cells and bricks.
        for (int a = 0; a < 3; ++a) map.offset[a] = -double(floorDiv(oriented.min[a], 8) * 8);
    } else {
        for (int a = 0; a < 3; ++a) map.offset[a] = -oriented.min[a] * map.scale[a];
    }
    map.exact = unitScale && map.offset == glm::floor(map.offset);
    im.plan.offset = map.offset;

    Box landed = map.span(oriented, 0.0);
    glm::ivec3& worldSize = place.worldSize;
    if (target) {
        worldSize = target->grid.sizeInVoxels();
    } else if (g.voxengine && map.exact && map.offset == glm::dvec3(0.0) && !upZ) {
        worldSize = g.worldHeader.size;
    } else {
        worldSize = glm::max(landed.max, glm::ivec3(1));
        glm::u64vec3 cells = glm::u64vec3((glm::dvec3(worldSize) + 7.0) / 8.0);
        if (glm::any(glm::greaterThan(worldSize, glm::ivec3(world::kMaxWorldExtent))) ||
            cells.x * cells.y * cells.z > world::kMaxTopGridCells)
            return makeError(
                "{}: the import would make a world of {}x{}x{} voxels, over the engine's limit ({} "
                "per "
                "axis, {} top-grid cells); use --voxel-size or --crop",
                im.file, worldSize.x, worldSize.y, worldSize.z, world::kMaxWorldExtent,
                world::kMaxTopGridCells);
    }
    place.worldBox = landed.intersect(Box{glm::ivec3(0), worldSize});
    if (place.worldBox.empty())
        return makeError(
            "{}: nothing of grid '{}' lands inside the world (check --offset and --crop)", im.file,
            im.plan.grid);
    if (landed.min != place.worldBox.min || landed.max != place.worldBox.max)
        im.plan.notes.push_back("part of the grid lands outside the world and is cut off");
    im.plan.worldBox = place.worldBox;
    im.plan.worldSize = ((worldSize + 7) / 8) * 8;
    return {};
}

}  // namespace engine::io::vdb_import
