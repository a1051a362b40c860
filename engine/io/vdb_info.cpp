#include "io/vdb_info.h"

#include <algorithm>
#include <fmt/format.h>

#include "core/quoted_string.h"
#include "io/vdb_layout.h"
#include "io/vdb_reader.h"

namespace engine::io {

namespace fs = std::filesystem;
namespace vdb = openvdb;

namespace {

// Text from the file (names, types, metadata) as one printable line, a long value cut short
// (at a character's start, not inside one).
std::string printable(std::string_view text) {
    std::string s = printableText(text);
    if (s.size() > 160) {
        std::size_t cut = 157;
        while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
        s = s.substr(0, cut) + "...";
    }
    return s;
}

std::vector<std::pair<std::string, std::string>> listMetadata(const vdb::MetaMap& meta) {
    std::vector<std::pair<std::string, std::string>> out;
    for (auto it = meta.beginMeta(); it != meta.endMeta(); ++it)
        out.emplace_back(printable(it->first), it->second ? printable(it->second->str()) : "?");
    return out;
}

std::string human(std::uint64_t bytes) {
    if (bytes >= (1u << 20)) return fmt::format("{:.2f} MiB", double(bytes) / (1 << 20));
    if (bytes >= (1u << 10)) return fmt::format("{:.1f} KiB", double(bytes) / (1 << 10));
    return fmt::format("{} B", bytes);
}

bool importableType(const vdb::GridBase& g) {
    return g.isType<vdb::FloatGrid>() || g.isType<vdb::DoubleGrid>() ||
           g.isType<vdb::Int32Grid>() || g.isType<vdb::Int64Grid>() || g.isType<vdb::BoolGrid>() ||
           g.isType<vdb::MaskGrid>() || g.isType<vdb::Vec3SGrid>() || g.isType<vdb::Vec3DGrid>();
}

std::string describeTransform(const vdb::math::Transform& xf) {
    if (!xf.isLinear()) return fmt::format("{} (not linear: cannot be imported)", xf.mapType());
    vdb::Mat4d m = xf.baseMap()->getAffineMap()->getMat4();
    double largest = 0.0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(m(r, c)));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (r != c && std::abs(m(r, c)) > 1e-6 * largest)
                return "rotated or sheared (cannot be imported)";
    vdb::Vec3d t = xf.indexToWorld(vdb::Vec3d(0.0));
    vdb::Vec3d s(m(0, 0), m(1, 1), m(2, 2));
    std::string scale = (s.x() == s.y() && s.x() == s.z())
                            ? fmt::format("uniform scale {:.6g}", s.x())
                            : fmt::format("scale {:.6g} x {:.6g} x {:.6g}", s.x(), s.y(), s.z());
    return fmt::format("{}, origin ({:.4g}, {:.4g}, {:.4g})", scale, t.x(), t.y(), t.z());
}

}  // namespace

Result<VdbFileInfo> describeVdbFile(const fs::path& path, const VdbImportOptions& importOptions) {
    auto bytes = vdbFileBytes(path);
    if (!bytes) return bytes.error();
    auto info =
        guardedVdbCall(path, importOptions.memoryBudgetBytes, *bytes, [&]() -> Result<VdbFileInfo> {
            VdbReader reader(path);
            VdbFileInfo out;
            out.path = path.string();
            out.fileBytes = reader.fileBytes();
            out.formatVersion = reader.formatVersion();
            out.libraryVersion = reader.libraryVersion();
            out.voxengine = vdb_layout::isVoxengineFile(reader.fileMetadata());
            out.metadata = listMetadata(reader.fileMetadata());
            for (std::size_t i = 0; i < reader.grids().size(); ++i) {
                const VdbReader::Entry& e = reader.grids()[i];
                VdbGridInfo g;
                g.name = printable(e.displayName);
                g.type = printable(e.type);
                if (!vdb::GridBase::isRegistered(e.type)) {
                    g.problem = "unknown grid type";
                    out.grids.push_back(std::move(g));
                    continue;
                }
                // One grid's topology at a time; a damaged grid is reported, not fatal to the
                // others.
                try {
                    vdb::GridBase::Ptr grid = reader.readHeader(i);
                    g.type = grid->valueType();
                    g.gridClass = vdb::GridBase::gridClassToString(grid->getGridClass());
                    g.transform = describeTransform(grid->transform());
                    vdb::Vec3d vs = grid->voxelSize();
                    g.voxelSize = glm::dvec3(vs.x(), vs.y(), vs.z());
                    g.metadata = listMetadata(*grid);
                    auto meta = [&](const char* key) {
                        return vdb::DynamicPtrCast<const vdb::Int64Metadata>((*grid)[key]);
                    };
                    auto coord = [&](const char* key) {
                        return vdb::DynamicPtrCast<const vdb::Vec3IMetadata>((*grid)[key]);
                    };
                    if (importableType(*grid)) {
                        grid = reader.readTopology(i);
                        g.activeVoxels = grid->activeVoxelCount();
                        g.leaves = grid->baseTree().leafCount();
                        g.activeTiles = grid->baseTree().activeTileCount();
                        vdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
                        if (!box.empty())
                            g.bounds = {
                                glm::ivec3(box.min().x(), box.min().y(), box.min().z()),
                                glm::ivec3(box.max().x(), box.max().y(), box.max().z()) + 1};
                        auto mem = meta(vdb::GridBase::META_FILE_MEM_BYTES);
                        g.memoryBytes = mem ? std::uint64_t(std::max<std::int64_t>(mem->value(), 0))
                                            : grid->memUsage();
                    } else {
                        // Not a type we load: report what the writer recorded about it.
                        g.note = "type not importable; counts from the file's metadata";
                        if (auto count = meta(vdb::GridBase::META_FILE_VOXEL_COUNT))
                            g.activeVoxels =
                                std::uint64_t(std::max<std::int64_t>(count->value(), 0));
                        if (auto mem = meta(vdb::GridBase::META_FILE_MEM_BYTES))
                            g.memoryBytes = std::uint64_t(std::max<std::int64_t>(mem->value(), 0));
                        auto lo = coord(vdb::GridBase::META_FILE_BBOX_MIN),
                             hi = coord(vdb::GridBase::META_FILE_BBOX_MAX);
                        if (lo && hi && g.activeVoxels > 0)
                            g.bounds = {
                                glm::ivec3(lo->value().x(), lo->value().y(), lo->value().z()),
                                glm::ivec3(hi->value().x(), hi->value().y(), hi->value().z()) + 1};
                    }
                } catch (const std::bad_alloc&) {
                    throw;  // over the budget: the whole call fails with the budget's message
                } catch (...) {
                    std::string message = vdbError(path, nullptr).message;
                    g.problem = message.substr(std::min(message.size(), path.string().size() + 2));
                }
                out.grids.push_back(std::move(g));
            }
            return out;
        });
    if (!info) return info;
    // The import plan runs under its own budget (it may pick a grid and read its topology again).
    info->import = planVdbImport(path, importOptions);
    return info;
}

std::string formatVdbFileInfo(const VdbFileInfo& info) {
    std::string s;
    s += fmt::format("file         {}\n", info.path);
    s += fmt::format("format       VDB file format {}, written by OpenVDB {} ({}){}\n",
                     info.formatVersion, info.libraryVersion, human(info.fileBytes),
                     info.voxengine ? "; a voxengine world" : "");
    if (!info.metadata.empty()) {
        s += fmt::format("metadata     {} entries\n", info.metadata.size());
        const std::size_t shown = std::min<std::size_t>(info.metadata.size(), 40);
        for (std::size_t i = 0; i < shown; ++i)
            s += fmt::format("  {:<28} {}\n", info.metadata[i].first, info.metadata[i].second);
        if (shown < info.metadata.size())
            s += fmt::format("  ... and {} more\n", info.metadata.size() - shown);
    }
    s += fmt::format("grids        {}\n", info.grids.size());
    for (const VdbGridInfo& g : info.grids) {
        s += fmt::format("  '{}': {}", g.name, g.type);
        if (!g.problem.empty()) {
            s += fmt::format(" -- {}\n", g.problem);
            continue;
        }
        s += fmt::format(", class {}{}\n", g.gridClass, g.note.empty() ? "" : " (" + g.note + ")");
        s +=
            fmt::format("    voxels     {} active ({} leaves, {} active tiles){}\n", g.activeVoxels,
                        g.leaves, g.activeTiles, g.activeVoxels == 0 ? ": empty" : "");
        if (!g.bounds.empty())
            s += fmt::format(
                "    bounds     [{}, {}, {}] .. [{}, {}, {}] ({} x {} x {}, index space)\n",
                g.bounds.min.x, g.bounds.min.y, g.bounds.min.z, g.bounds.max.x, g.bounds.max.y,
                g.bounds.max.z, g.bounds.size().x, g.bounds.size().y, g.bounds.size().z);
        s += fmt::format("    transform  {}\n", g.transform);
        s += fmt::format("    memory     {} when loaded\n", human(g.memoryBytes));
        std::size_t extra = 0;
        for (const auto& [key, value] : g.metadata) {
            if (key.rfind("file_", 0) == 0 || key == "name" || key == "class") continue;
            if (++extra > 12) continue;
            s += fmt::format("    {:<10} {}\n", key, value);
        }
        if (extra > 12) s += fmt::format("    ... and {} more metadata entries\n", extra - 12);
    }
    if (info.import.ok()) {
        s += "import would\n";
        s += formatVdbImportPlan(info.import.value());
    } else {
        s += fmt::format("import       not possible: {}\n", info.import.error().message);
    }
    return s;
}

}  // namespace engine::io
