#include "io/vdb_reader.h"

#include <algorithm>
#include <fmt/format.h>
#include <memory>
#include <mutex>
#include <new>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <system_error>
#include <type_traits>

#include "core/memory_budget.h"
#include "core/quoted_string.h"
#include "io/vdb_tree_stream.h"

namespace engine::io {

void linkOpenVdbDecoders();  // io/openvdb_decoders.cpp

namespace fs = std::filesystem;
namespace vdb = openvdb;

namespace {

constexpr std::int64_t kVdbMagic = 0x56444220;
constexpr char kHalfFloatSuffix[] = "_HalfFloat";

// Text from the file (a grid's name or type, OpenVDB's message quoting it) as one printable
// line (core/quoted_string.h), a long one cut short.
std::string oneLine(std::string_view text) {
    std::string s = printableText(text);
    if (s.size() > 300) {
        std::size_t cut = 300;
        while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
        s = s.substr(0, cut) + "...";
    }
    return s;
}

std::string mib(std::uint64_t bytes) {
    return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20));
}

// OpenVDB's what() reads "IoError: detail"; keep the detail.
std::string detail(const vdb::Exception& e) {
    std::string what = e.what() ? e.what() : "";
    std::size_t colon = what.find(": ");
    if (colon != std::string::npos && colon < 24 && what.find(' ') > colon)
        what = what.substr(colon + 2);
    return oneLine(what);
}

// Every tree is walked (io/vdb_tree_stream.h) before OpenVDB reads it. Why: OpenVDB 10's
// RootNode::readTopology() allocates each top-level child with a bare `new` and stores it only
// after the child's subtree has been read, and overwrites a child with a later one of the same
// origin; a damaged file therefore leaks (or worse) when reading throws half way. Walking first
// means OpenVDB only ever reads topology known to be good, with its memory needs known.
// Grid types whose topology can be checked (and so read); the ones import and info use.
template <typename F>
bool withCheckedTreeType(const vdb::GridBase& g, F&& f) {
    if (g.isType<vdb::FloatGrid>()) return f(static_cast<vdb::FloatTree*>(nullptr)), true;
    if (g.isType<vdb::DoubleGrid>()) return f(static_cast<vdb::DoubleTree*>(nullptr)), true;
    if (g.isType<vdb::Int32Grid>()) return f(static_cast<vdb::Int32Tree*>(nullptr)), true;
    if (g.isType<vdb::Int64Grid>()) return f(static_cast<vdb::Int64Tree*>(nullptr)), true;
    if (g.isType<vdb::BoolGrid>()) return f(static_cast<vdb::BoolTree*>(nullptr)), true;
    if (g.isType<vdb::MaskGrid>()) return f(static_cast<vdb::MaskTree*>(nullptr)), true;
    if (g.isType<vdb::Vec3SGrid>()) return f(static_cast<vdb::Vec3STree*>(nullptr)), true;
    if (g.isType<vdb::Vec3DGrid>()) return f(static_cast<vdb::Vec3DTree*>(nullptr)), true;
    return false;
}

}  // namespace

void initializeOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] {
        vdb::initialize();
        // OpenVDB 10 decodes a grid's delayed-load tables ("__delayedload" metadata) with blosc
        // as soon as it reads the grid's metadata, and blosc crashes on damaged input (found by
        // the fuzz target). We never delay-load: unregistered, the tables are read as opaque
        // bytes and dropped.
        if (vdb::io::DelayedLoadMetadata::isRegisteredType())
            vdb::io::DelayedLoadMetadata::unregisterType();
    });
}

std::uint64_t vdbSingleAllocationLimit(std::uint64_t fileBytes) {
    return fileBytes + (16ull << 20);
}

Result<std::uint64_t> vdbFileBytes(const fs::path& path) {
    std::error_code ec;
    fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) return makeError("{}: cannot open: no such file", path.string());
    if (!fs::is_regular_file(st))
        return makeError("{}: cannot open: not a regular file", path.string());
    std::uint64_t bytes = fs::file_size(path, ec);
    if (ec) return makeError("{}: cannot open: {}", path.string(), ec.message());
    if (bytes == 0) return makeError("{}: empty file (0 bytes), not a VDB file", path.string());
    return bytes;
}

Error vdbError(const fs::path& path, const AllocationBudget* budget) {
    const std::string file = path.string();
    try {
        throw;
    } catch (const std::bad_alloc&) {
        if (budget && budget->refusedAsSingleRequest()) {
            // Not a question of the budget: no legitimate read needs one buffer this large.
            return makeError(
                "{}: reading it asks for {} bytes of memory in one block, more than any valid file "
                "of "
                "this size needs ({}: its size plus 16 MiB); the file is damaged (or, if OpenVDB's "
                "vdb_print reads it, this is a bug in vox)",
                file, budget->refusedBytes(), budget->singleBytes());
        }
        if (budget && budget->exceeded()) {
            return makeError(
                "{}: reading it needs more memory than the budget of {} allows (a request for {} "
                "bytes was "
                "refused); the file is damaged or too large ({})",
                file, mib(budget->totalBytes()), budget->refusedBytes(),
                memoryBudgetAdvice(budget->totalBytes()));
        }
        return makeError("{}: out of memory while reading", file);
    } catch (const std::ios_base::failure&) {
        return makeError("{}: truncated or corrupt VDB file (data ends or points outside the file)",
                         file);
    } catch (const vdb::IoError& e) {
        std::string what = detail(e);
        if (what.find("not a VDB file") != std::string::npos)
            return makeError("{}: not a VDB file", file);
        return makeError("{}: truncated or corrupt VDB file ({})", file, what);
    } catch (const vdb::Exception& e) {
        return makeError("{}: truncated, corrupt or unsupported VDB file ({})", file, detail(e));
    } catch (const std::exception& e) {
        return makeError("{}: cannot read VDB file ({})", file, oneLine(e.what()));
    } catch (...) {
        return makeError("{}: cannot read VDB file (unknown error)", file);
    }
}

VdbReader::VdbReader(const fs::path& path) : mPath(path) {
    initializeOpenVdb();
    std::error_code ec;
    mFileBytes = fs::file_size(path, ec);
    if (ec) throw vdb::IoError("cannot open " + path.string());
    mStream.open(path, std::ios::in | std::ios::binary);
    if (!mStream) throw vdb::IoError("cannot open " + path.string());
    // From here on any short read or bad seek throws instead of leaving garbage behind.
    mStream.exceptions(std::ios::failbit | std::ios::badbit);

    linkOpenVdbDecoders();
    std::int64_t magic = 0;
    std::uint32_t version = 0;
    if (mFileBytes < sizeof(magic) + sizeof(version)) throw vdb::IoError("not a VDB file");
    mStream.read(reinterpret_cast<char*>(&magic), sizeof(magic));
    if (magic != kVdbMagic) throw vdb::IoError("not a VDB file");
    // Checked here because OpenVDB only warns (on stderr) and then reads on regardless.
    mStream.read(reinterpret_cast<char*>(&version), sizeof(version));
    if (version > vdb::OPENVDB_FILE_VERSION)
        throw vdb::IoError(
            fmt::format("file format {} is newer than this build's OpenVDB reads ({})", version,
                        vdb::OPENVDB_FILE_VERSION));
    mStream.seekg(0);

    Archive::readHeader(mStream);
    mFormatVersion = fileVersion();
    if (mFormatVersion < vdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)
        throw vdb::IoError(fmt::format(
            "file format {} predates OpenVDB 3 (format {}); re-save it with a newer OpenVDB",
            mFormatVersion, int(vdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)));
    if (!inputHasGridOffsets())
        throw vdb::IoError("file has no grid offsets (written as a stream), not supported");

    mStreamMetadata = std::make_shared<vdb::io::StreamMetadata>();
    mStreamMetadata->setSeekable(true);
    vdb::io::setStreamMetadataPtr(mStream, mStreamMetadata, /*transfer=*/false);
    setFormatVersion(mStream);
    setLibraryVersion(mStream);
    setDataCompression(mStream);

    mFileMetadata.readMeta(mStream);

    auto remaining = [&] { return mFileBytes - std::uint64_t(mStream.tellg()); };
    auto readString = [&] {
        std::uint32_t n = 0;
        mStream.read(reinterpret_cast<char*>(&n), sizeof(n));
        if (n > remaining()) throw std::ios_base::failure("string runs past the end of the file");
        std::string s(n, '\0');
        if (n) mStream.read(s.data(), n);
        return s;
    };
    std::int32_t count = 0;
    mStream.read(reinterpret_cast<char*>(&count), sizeof(count));
    if (count < 0 || std::uint64_t(count) > remaining() / 36)
        throw vdb::IoError(fmt::format("grid count {} does not fit in the file", count));

    // Descriptors are parsed here rather than by GridDescriptor::read(), which throws on the
    // first unregistered grid type and so would hide every other grid of the file.
    for (std::int32_t i = 0; i < count; ++i) {
        Entry e;
        e.uniqueName = readString();
        e.type = readString();
        e.parent = readString();
        bool half = false;
        const std::size_t suffix = sizeof(kHalfFloatSuffix) - 1;
        if (e.type.size() > suffix &&
            e.type.compare(e.type.size() - suffix, suffix, kHalfFloatSuffix) == 0) {
            e.type.resize(e.type.size() - suffix);
            half = true;
        }
        e.name = vdb::io::GridDescriptor::stripSuffix(e.uniqueName);
        e.displayName = printableText(vdb::io::GridDescriptor::nameAsString(e.uniqueName));
        std::int64_t pos[3];
        mStream.read(reinterpret_cast<char*>(pos), sizeof(pos));
        const std::int64_t here = mStream.tellg();
        // An instance stores only metadata and transform (its tree is its parent's), and OpenVDB
        // writes its block offset as 0.
        const bool blocksInOrder =
            e.parent.empty() ? pos[0] <= pos[1] && pos[1] <= pos[2] : pos[1] == 0;
        if (!(here <= pos[0] && pos[0] <= pos[2] && blocksInOrder &&
              std::uint64_t(pos[2]) <= mFileBytes))
            throw vdb::IoError(fmt::format("grid '{}' reaches past the end of the file's {} bytes",
                                           oneLine(e.name), mFileBytes));
        vdb::io::GridDescriptor gd(e.uniqueName, e.type, half);
        gd.setInstanceParentName(e.parent);
        gd.setGridPos(pos[0]);
        gd.setBlockPos(pos[1]);
        gd.setEndPos(pos[2]);
        mEntries.push_back(std::move(e));
        mDescriptors.push_back(gd);
        mStream.seekg(pos[2]);
    }
}

std::string VdbReader::libraryVersion() const {
    vdb::VersionId v = Archive::libraryVersion();
    return fmt::format("{}.{}", v.first, v.second);
}

int VdbReader::find(const std::string& name) const {
    for (std::size_t i = 0; i < mEntries.size(); ++i)
        if (mEntries[i].name == name || mEntries[i].uniqueName == name ||
            mEntries[i].displayName == name)
            return int(i);
    // "name[0]": the first of several grids with that name (OpenVDB numbers only the later ones).
    const std::string first = "[0]";
    if (name.size() > first.size() &&
        name.compare(name.size() - first.size(), first.size(), first) == 0) {
        const std::string base = name.substr(0, name.size() - first.size());
        for (std::size_t i = 0; i < mEntries.size(); ++i)
            if (mEntries[i].uniqueName == base) return int(i);
    }
    return -1;
}

std::size_t VdbReader::treeSource(std::size_t index) const {
    // Follow instance links to the grid that stores the tree; a chain longer than the grid count
    // is a cycle in a damaged file.
    for (std::size_t hops = 0; hops <= mEntries.size(); ++hops) {
        const std::string& parent = mEntries[index].parent;
        if (parent.empty()) return index;
        auto it = std::find_if(mEntries.begin(), mEntries.end(),
                               [&](const Entry& e) { return e.uniqueName == parent; });
        if (it == mEntries.end())
            throw vdb::KeyError("grid '" + oneLine(mEntries[index].name) +
                                "' is an instance of a missing grid");
        index = std::size_t(it - mEntries.begin());
    }
    throw vdb::KeyError("grid instances form a cycle");
}

vdb::GridBase::Ptr VdbReader::readHeader(std::size_t index) {
    return read(index, Depth::Header, vdb::CoordBBox());
}
vdb::GridBase::Ptr VdbReader::readTopology(std::size_t index) {
    return read(index, Depth::Topology, vdb::CoordBBox());
}
vdb::GridBase::Ptr VdbReader::readRegion(std::size_t index, const vdb::CoordBBox& clip) {
    return read(index, Depth::Region, clip);
}

vdb::GridBase::Ptr VdbReader::openTree(std::size_t index) {
    const vdb::io::GridDescriptor& gd = mDescriptors.at(index);
    if (gd.isInstance())
        throw vdb::TypeError("grid '" + oneLine(gd.gridName()) + "' is an instance; read it whole");
    vdb::GridBase::Ptr grid = readGridStart(index);
    return grid;  // the stream is at the topology, with this grid's state set until the next read
}

void VdbReader::seekToBuffers(std::size_t index) {
    mStream.clear();
    mDescriptors.at(index).seekToBlocks(mStream);
}

vdb::GridBase::Ptr VdbReader::readGridStart(std::size_t index) {
    const vdb::io::GridDescriptor& gd = mDescriptors.at(index);
    if (!vdb::GridBase::isRegistered(gd.gridType()))
        throw vdb::TypeError("grid '" + oneLine(gd.gridName()) + "' has the unknown type " +
                             oneLine(gd.gridType()));
    vdb::GridBase::Ptr grid = vdb::GridBase::createGrid(gd.gridType());
    grid->setSaveFloatAsHalf(gd.saveFloatAsHalf());
    mStream.clear();
    // The same per-grid stream set-up as io::Archive::readGrid(): grid class, background and
    // half-float flags travel with the stream and steer how node values decode.
    gd.seekToGrid(mStream);
    mGridStreamMetadata = std::make_shared<vdb::io::StreamMetadata>(*mStreamMetadata);
    mGridStreamMetadata->setHalfFloat(grid->saveFloatAsHalf());
    vdb::io::setStreamMetadataPtr(mStream, mGridStreamMetadata, /*transfer=*/false);
    vdb::io::setGridClass(mStream, vdb::GRID_UNKNOWN);
    vdb::io::setGridBackgroundValuePtr(mStream, nullptr);
    readGridCompression(mStream);
    grid->readMeta(mStream);
    // Per-leaf sizes for delayed loading: we never delay-load, and OpenVDB 10 trusts this
    // table's length when skipping leaves (it asserts, or reads past the end).
    grid->removeMeta(vdb::GridBase::META_FILE_DELAYED_LOAD);
    mGridStreamMetadata->gridMetadata() = static_cast<vdb::MetaMap&>(*grid);
    vdb::io::setGridClass(mStream, grid->getGridClass());
    grid->readTransform(mStream);
    if (grid->getName().empty()) grid->setName(gd.gridName());
    return grid;
}

vdb::GridBase::Ptr VdbReader::read(std::size_t index, Depth depth, const vdb::CoordBBox& clip) {
    const vdb::io::GridDescriptor& gd = mDescriptors.at(index);
    // Point grids (multi-pass attribute buffers) hold particles, not voxels.
    const bool points = gd.gridType().find("ptdataidx") != std::string::npos ||
                        gd.gridType().find("ptidx") != std::string::npos;
    if (points && depth != Depth::Header)
        throw vdb::TypeError("grid '" + oneLine(gd.gridName()) +
                             "' is a point grid, which cannot be read as voxels");
    struct Restore {
        VdbReader& r;
        ~Restore() { vdb::io::setStreamMetadataPtr(r.mStream, r.mStreamMetadata, false); }
    } restore{*this};
    vdb::GridBase::Ptr grid = readGridStart(index);
    if (depth == Depth::Header) return grid;

    if (gd.isInstance()) {
        std::size_t source = treeSource(index);
        vdb::GridBase::Ptr parent = read(source, depth, clip);
        if (parent->type() != grid->type())
            throw vdb::TypeError("grid instance of a different type");
        grid->setTree(parent->baseTreePtr());
        return grid;
    }
    const std::streamoff topology = mStream.tellg();
    TreeBytes bytes;
    const bool checked = withCheckedTreeType(*grid, [&](auto* tree) {
        using TreeT = std::remove_pointer_t<decltype(tree)>;
        bytes = TreeStream<TreeT>::walk(mStream, mFormatVersion, grid->saveFloatAsHalf(),
                                        mFileBytes, depth == Depth::Region ? &clip : nullptr, {})
                    .bytes;
    });
    if (!checked)
        throw vdb::TypeError("grid '" + oneLine(gd.gridName()) + "' has type " + grid->valueType() +
                             ", whose nodes this reader does not load");
    // Refuse here, not inside OpenVDB: its tree reading is not exception-safe (a bad_alloc in
    // the middle leaks or half-builds nodes), so it runs with headroom checked in advance and
    // the budget enforced again right after.
    const std::uint64_t expected = bytes.nodes + bytes.leafValues;
    AllocationBudget::Headroom headroom(expected + expected / 8 + (1 << 20));
    mStream.seekg(topology);
    grid->readTopology(mStream);
    if (depth == Depth::Region) grid->readBuffers(mStream, clip);
    headroom.finish();
    return grid;
}

}  // namespace engine::io
