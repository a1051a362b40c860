// Choosing what an OpenVDB import reads: the shape grid (named, ours, or the first usable
// non-empty one), its transform's check, the colour grid and the material rule
// (io/vdb_import_state.h).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <vector>

#include "core/quoted_string.h"
#include "io/vdb_import_state.h"
#include "world/world_limits.h"

namespace engine::io::vdb_import {

namespace vdb = openvdb;

namespace {

bool isColourName(std::string name) {
    for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    return name == "color" || name == "colour" || name == "cd" || name == "albedo" || name == "rgb";
}

Status checkTransform(const ImportState& im, const vdb::GridBase& g) {
    const vdb::math::Transform& xf = g.transform();
    const std::string name = printableText(g.getName());
    if (!xf.isLinear())
        return makeError(
            "{}: grid '{}' has a non-linear ({}) transform; only axis-aligned scale and "
            "translation "
            "can be imported",
            im.file, name, xf.mapType());
    vdb::Mat4d m = xf.baseMap()->getAffineMap()->getMat4();
    double largest = 0.0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(m(r, c)));
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(m(r, c)))
                return makeError("{}: grid '{}' has a transform that is not finite", im.file, name);
            if (r != c && std::abs(m(r, c)) > 1e-6 * largest)
                return makeError(
                    "{}: grid '{}' has a rotated or sheared transform; only axis-aligned scale and "
                    "translation can be imported",
                    im.file, name);
        }
        if (!(m(r, r) > 0.0))
            return makeError(
                "{}: grid '{}' has a mirrored or degenerate transform (scale {} on axis {})",
                im.file, name, m(r, r), "xyz"[r]);
    }
    return {};
}

// The grid to import: the one named, our own material grid, or the first usable non-empty one.
Status findShapeGrid(ImportState& im) {
    const auto& entries = im.reader.grids();
    const std::string& file = im.file;
    if (entries.empty()) return makeError("{}: the file holds no grids", file);
    auto describe = [&](std::size_t i, const vdb::GridBase* g, const char* state) {
        return fmt::format("{} ({}{}{})", entries[i].displayName,
                           g ? g->valueType() : printableText(entries[i].type), *state ? ", " : "",
                           state);
    };
    std::vector<vdb::GridBase::Ptr> headers(entries.size());
    auto header = [&](std::size_t i) -> vdb::GridBase::Ptr {
        if (!headers[i] && vdb::GridBase::isRegistered(entries[i].type))
            headers[i] = im.reader.readHeader(i);
        return headers[i];
    };
    auto isEmpty = [&](std::size_t i) {
        // OpenVDB writers store the active voxel count as metadata; read the topology otherwise.
        vdb::GridBase::Ptr g = header(i);
        if (auto count = vdb::DynamicPtrCast<const vdb::Int64Metadata>(
                (*g)[vdb::GridBase::META_FILE_VOXEL_COUNT]))
            if (count->value() > 0) return false;
        vdb::GridBase::Ptr t = im.reader.readTopology(i);
        if (t->activeVoxelCount() > 0) return false;
        // A level set may be all interior tiles (inactive, negative).
        if (kindOf(*t) == Kind::LevelSet) {
            auto source = makeSource(*t);
            source->attach(t);
            bool inside = false;
            (void)source->forEachTile([&](const vdb::CoordBBox&, const Sample& s) {
                inside |= s.scalar < 0.0;
                return Status{};
            });
            return !inside && t->baseTree().leafCount() == 0;
        }
        return true;
    };

    auto choose = [&](std::size_t i) -> Status {
        im.grids.shapeIndex = i;
        im.grids.shapeHeader = header(i);
        return {};
    };
    auto unusable = [&](const std::string& name, std::size_t i, const vdb::GridBase* g) {
        return makeError(
            "{}: grid '{}' has type {}, which cannot be imported (usable: float/double level sets "
            "and "
            "fog volumes, int32/int64 ids, bool/mask, vec3 colours)",
            file, name, g ? g->valueType() : entries[i].type);
    };

    const VdbImportOptions& o = im.options;
    if (!o.grid.empty()) {
        const int chosen = im.reader.find(o.grid);
        if (chosen < 0) {
            std::string names;
            for (const auto& e : entries) names += (names.empty() ? "" : ", ") + e.displayName;
            return makeError("{}: no grid named '{}' (grids: {})", file, o.grid, names);
        }
        vdb::GridBase::Ptr g = header(std::size_t(chosen));
        if (!g || !kindOf(*g)) return unusable(o.grid, std::size_t(chosen), g.get());
        if (isEmpty(std::size_t(chosen)))
            return makeError("{}: grid '{}' is empty (no active voxels)", file, o.grid);
        return choose(std::size_t(chosen));
    }
    if (im.grids.voxengine) {
        const int chosen = im.reader.find(vdb_layout::kMaterialGrid);
        if (chosen < 0)
            return makeError("{}: voxengine file without its '{}' grid", file,
                             vdb_layout::kMaterialGrid);
        vdb::GridBase::Ptr g = header(std::size_t(chosen));
        if (!g || !kindOf(*g))
            return unusable(vdb_layout::kMaterialGrid, std::size_t(chosen), g.get());
        return choose(std::size_t(chosen));
    }
    // The first usable non-empty grid, scalar grids before vec3 ones.
    std::vector<std::string> why;
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t i = 0; i < entries.size(); ++i) {
            vdb::GridBase::Ptr g = header(i);
            if (!g || !kindOf(*g)) {
                if (pass == 0) why.push_back(describe(i, g.get(), "unusable type"));
                continue;
            }
            if ((kindOf(*g) == Kind::Colour) != (pass == 1)) continue;
            if (isEmpty(i)) {
                why.push_back(describe(i, g.get(), "empty"));
                continue;
            }
            return choose(i);
        }
    }
    std::string list;
    for (const auto& w : why) list += (list.empty() ? "" : ", ") + w;
    return makeError("{}: nothing to import: no grid is both usable and non-empty ({})", file,
                     list);
}

Status selectShapeGrid(ImportState& im) {
    if (Status s = findShapeGrid(im); !s) return s;
    ChosenGrids& g = im.grids;
    const auto& entries = im.reader.grids();
    g.kind = *kindOf(*g.shapeHeader);
    const bool ownMaterials = entries[g.shapeIndex].name == vdb_layout::kMaterialGrid;
    if (g.voxengine && ownMaterials && g.shapeHeader->isType<vdb::Int32Grid>())
        g.kind = Kind::VoxIds;
    // Our Z-up exports turn the transform a quarter about x; index space is still ours.
    const bool ourZUp =
        g.voxengine && g.worldHeader.zUp &&
        g.shapeHeader->transform() == *vdb_layout::gridTransform(g.worldHeader.voxelSize, true);
    if (!ourZUp)
        if (Status s = checkTransform(im, *g.shapeHeader); !s) return s;
    g.shapeXform = g.shapeHeader->transformPtr();
    im.plan.grid = entries[g.shapeIndex].displayName;
    im.plan.gridType = g.shapeHeader->valueType();
    im.plan.gridClass = vdb::GridBase::gridClassToString(g.shapeHeader->getGridClass());
    im.plan.kind = kindName(g.kind);
    im.plan.voxengine = g.voxengine;
    return {};
}

// A vec3 grid to colour a non-colour shape: the one named, else one with a colour's name.
Status selectColourGrid(ImportState& im) {
    ChosenGrids& g = im.grids;
    const VdbImportOptions& o = im.options;
    const auto& entries = im.reader.grids();
    const bool wantColour = o.rule == MaterialRule::Colour || o.rule == MaterialRule::Auto;
    if (!wantColour || g.kind == Kind::Colour || g.kind == Kind::Ids || g.kind == Kind::VoxIds)
        return {};
    int found = -1;
    if (!o.colourGrid.empty()) {
        found = im.reader.find(o.colourGrid);
        if (found < 0) return makeError("{}: no colour grid named '{}'", im.file, o.colourGrid);
    } else {
        for (std::size_t i = 0; i < entries.size() && found < 0; ++i)
            if (i != g.shapeIndex && isColourName(entries[i].name)) found = int(i);
    }
    if (found < 0) return {};
    const auto& entry = entries[std::size_t(found)];
    if (!vdb::GridBase::isRegistered(entry.type))
        return makeError("{}: colour grid '{}' has the unknown type {}", im.file, entry.displayName,
                         printableText(entry.type));
    vdb::GridBase::Ptr h = im.reader.readHeader(std::size_t(found));
    if (isColourType(*h)) {
        g.colourIndex = found;
        g.colourXform = h->transformPtr();
        g.sameXform = *g.colourXform == *g.shapeXform;
        im.plan.colourGrid = entry.displayName;
    } else if (!o.colourGrid.empty()) {
        return makeError("{}: colour grid '{}' has type {}, not vec3", im.file, o.colourGrid,
                         h->valueType());
    }
    return {};
}

Status selectMaterialRule(ImportState& im) {
    ChosenGrids& g = im.grids;
    const VdbImportOptions& o = im.options;
    switch (o.rule) {
        case MaterialRule::Auto:
            if (g.kind == Kind::VoxIds || g.kind == Kind::Ids)
                g.rule = MaterialRule::Ids;
            else if (g.kind == Kind::Colour || g.colourIndex >= 0)
                g.rule = MaterialRule::Colour;
            else
                g.rule = MaterialRule::Constant;
            break;
        case MaterialRule::Ids:
            if (g.kind != Kind::VoxIds && g.kind != Kind::Ids)
                return makeError("{}: the ids rule needs an integer grid; '{}' is {}", im.file,
                                 im.plan.grid, im.plan.gridType);
            g.rule = o.rule;
            break;
        case MaterialRule::Colour:
            if (g.kind != Kind::Colour && g.colourIndex < 0)
                return makeError(
                    "{}: the colour rule needs a vec3 colour grid (name one with --colour-grid)",
                    im.file);
            g.rule = o.rule;
            break;
        default:
            g.rule = o.rule;
    }
    if (g.rule == MaterialRule::Height)
        g.heightBands = int(o.heightMaterials.empty() ? 4 : o.heightMaterials.size());
    switch (g.rule) {
        case MaterialRule::Ids:
            im.plan.rule = g.kind == Kind::VoxIds ? "the file's palette (exact)"
                                                  : "one material per distinct value";
            break;
        case MaterialRule::Colour: {
            const std::string& colours =
                g.colourIndex >= 0 ? im.reader.grids()[std::size_t(g.colourIndex)].displayName
                                   : im.plan.grid;
            im.plan.rule = fmt::format("colours of '{}' quantised to at most {} materials", colours,
                                       o.maxColours);
            break;
        }
        case MaterialRule::Height:
            im.plan.rule = fmt::format("{} bands by height", g.heightBands);
            break;
        default:
            im.plan.rule = fmt::format("constant '{}'", o.material.name);
    }
    if (o.maxColours < 1 || std::size_t(o.maxColours) >= world::kMaxMaterials)
        return makeError("{}: the colour count must be in 1..{}", im.file,
                         world::kMaxMaterials - 1);
    return {};
}

}  // namespace

Status chooseGrids(ImportState& im) {
    im.grids.voxengine = vdb_layout::isVoxengineFile(im.reader.fileMetadata());
    if (im.grids.voxengine) {
        auto header = vdb_layout::readWorldMetadata(im.reader.fileMetadata(), im.file);
        if (!header) return header.error();
        im.grids.worldHeader = std::move(*header);
    }
    if (Status s = selectShapeGrid(im); !s) return s;
    if (Status s = selectColourGrid(im); !s) return s;
    return selectMaterialRule(im);
}

}  // namespace engine::io::vdb_import
