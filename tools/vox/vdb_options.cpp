#include "vdb_options.h"

#include <cmath>
#include <cstdio>

#include "commands.h"
#include "core/memory_budget.h"
#include "number_options.h"

namespace vox {

void addVdbImportOptions(CLI::App& cmd, VdbCliOptions& o) {
    cmd.add_option("--grid", o.grid,
                   "Grid to import (default: ours, else the first usable non-empty grid); of "
                   "several grids with "
                   "one name, NAME[0], NAME[1]... as `vox info` lists them");
    cmd.add_option("--colour-grid", o.colourGrid,
                   "vec3 grid giving colours (default: one named color/colour/Cd/albedo/rgb)");
    cmd.add_option("--material", o.rule, "Material rule: auto, constant, height, colour, ids")
        ->capture_default_str();
    cmd.add_option("--albedo", o.albedo, "Albedo r,g,b of the constant material (linear, 0..1)");
    cmd.add_option("--fog-threshold", o.fogThreshold, "Fog volumes: solid where density >= this")
        ->capture_default_str()
        ->check(numberIn(engine::closedRange(-1e6, 1e6)));
    cmd.add_option("--max-colours", o.maxColours, "Colour rule: at most this many materials")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 65534, "materials")));
    cmd.add_option("--voxel-size", o.voxelSize,
                   "Resample to this voxel size (file units; default: the file's)")
        ->check(numberIn(engine::aboveRange(0.0, 1e6, "file units")));
    cmd.add_option("--offset", o.offset,
                   "x,y,z: world voxel where source voxel (0,0,0) lands (default: auto)");
    cmd.add_option("--crop", o.crop,
                   "x0,y0,z0,x1,y1,z1: import only this source index box (max exclusive)");
    cmd.add_option("--up", o.up, "Source up axis: y, z or auto (auto: z for Blender files)")
        ->capture_default_str();
    cmd.add_option("--memory-budget", o.memoryBudgetMiB,
                   "MiB an import (and the world it makes) may take; refused above it (imports "
                   "default to 4096)")
        ->capture_default_str()
        ->check(numberIn(engine::wholeRange(1, 1 << 24, "MiB")));
}

engine::Result<engine::io::VdbImportOptions> toImportOptions(const VdbCliOptions& o) {
    using engine::makeError;
    namespace io = engine::io;
    io::VdbImportOptions out;
    out.grid = o.grid;
    out.colourGrid = o.colourGrid;
    if (o.rule == "auto")
        out.rule = io::MaterialRule::Auto;
    else if (o.rule == "constant")
        out.rule = io::MaterialRule::Constant;
    else if (o.rule == "height")
        out.rule = io::MaterialRule::Height;
    else if (o.rule == "colour" || o.rule == "color")
        out.rule = io::MaterialRule::Colour;
    else if (o.rule == "ids")
        out.rule = io::MaterialRule::Ids;
    else
        return makeError(
            "--material: unknown rule '{}' (known: auto, constant, height, colour, ids)", o.rule);
    if (!o.albedo.empty()) {
        auto a = parseVec3(o.albedo, "--albedo", engine::closedRange(0.0, 1.0));
        if (!a) return a.error();
        out.material.albedo = *a;
    }
    if (!(o.fogThreshold == o.fogThreshold)) return makeError("--fog-threshold: not a number");
    out.fogThreshold = o.fogThreshold;
    if (o.maxColours < 1 || o.maxColours > 65534)
        return makeError("--max-colours: must be in 1..65534");
    out.maxColours = o.maxColours;
    // Checked by numberIn as given, and kept as given (a double): the import says why a size is
    // too small for the file (its resampling range), not that it became 0.
    out.voxelSize = o.voxelSize;
    if (!o.offset.empty()) {
        int x, y, z;
        char extra;
        if (std::sscanf(o.offset.c_str(), "%d,%d,%d%c", &x, &y, &z, &extra) != 3)
            return makeError("--offset: expected x,y,z in whole voxels, got '{}'", o.offset);
        out.offset = glm::ivec3(x, y, z);
    }
    if (!o.crop.empty()) {
        int v[6];
        char extra;
        if (std::sscanf(o.crop.c_str(), "%d,%d,%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &v[4],
                        &v[5], &extra) != 6)
            return makeError("--crop: expected x0,y0,z0,x1,y1,z1, got '{}'", o.crop);
        engine::world::Box box{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
        if (box.empty())
            return makeError("--crop: the max corner must exceed the min corner on every axis");
        out.crop = box;
    }
    if (o.up == "auto")
        out.up = io::UpAxis::Auto;
    else if (o.up == "y")
        out.up = io::UpAxis::Y;
    else if (o.up == "z")
        out.up = io::UpAxis::Z;
    else
        return makeError("--up: expected y, z or auto, got '{}'", o.up);
    if (!(o.memoryBudgetMiB >= 1.0 && o.memoryBudgetMiB <= 1 << 24))
        return makeError("--memory-budget: must be in 1..16777216 MiB");
    out.memoryBudgetBytes = std::uint64_t(o.memoryBudgetMiB * double(1 << 20));
    // Given here, it is the process's budget too (the import's world is then shown or saved).
    if (o.memoryBudgetMiB != double(engine::io::kDefaultVdbMemoryBudget >> 20))
        engine::setMemoryBudgetBytes(out.memoryBudgetBytes);
    return out;
}

}  // namespace vox
