// VdbReader: reads .vdb files defensively, for import and `vox info`. Internal to engine/io (it
// exposes OpenVDB types; only engine/io/vdb_*.cpp include it).
//
// Built on io::Archive's protected stream API instead of io::File, for two reasons:
//  - the input stream throws on every short read and failed seek. OpenVDB does not check its
//    reads: after a truncation it keeps looping over garbage counts and sizes (a 4 GiB string
//    filled with spaces, billions of root tiles), so without this a damaged file hangs the
//    program instead of failing;
//  - a grid can be read a region at a time. Leaves outside the index-space clip box are skipped
//    by seeking, never decompressed, so import holds one slab of the source at a time.
// The topology alone (nodes, masks and tile values, no leaf values) can also be read, for
// planning and for `vox info`.
//
// All functions throw (std::ios_base::failure, openvdb::Exception, std::bad_alloc); callers
// convert at the io boundary with guardedVdbCall() so a message names the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <openvdb/openvdb.h>
#include <string>
#include <vector>

#include "core/allocation_budget.h"
#include "core/error.h"

namespace engine::io {

class VdbReader : private openvdb::io::Archive {
public:
    struct Entry {
        std::string name;  // grid name (unique name without the "[n]" suffix)
        std::string
            uniqueName;  // as stored: OpenVDB numbers grids of a repeated name "\x1e0", "\x1e1"...
        std::string displayName;  // OpenVDB's printable form: "density[0]", "density[1]"... (else
                                  // the name), control characters escaped (core/quoted_string.h)
        std::string type;         // e.g. "Tree_float_5_4_3"
        std::string parent;       // instance parent's unique name, empty when not an instance
    };

    // Reads the header, file metadata and grid descriptors.
    explicit VdbReader(const std::filesystem::path& path);

    const std::filesystem::path& path() const { return mPath; }
    std::uint64_t fileBytes() const { return mFileBytes; }
    std::uint32_t formatVersion() const { return mFormatVersion; }
    std::string libraryVersion() const;
    const openvdb::MetaMap& fileMetadata() const { return mFileMetadata; }
    const std::vector<Entry>& grids() const { return mEntries; }
    // Index of the grid named `name`, or -1. A plain name picks the first grid of that name;
    // "name[0]", "name[1]"... each grid of a repeated name ("name[0]" also when the first one
    // was stored without a number, as writers other than OpenVDB 10 may do).
    int find(const std::string& name) const;

    // Metadata and transform, no tree.
    openvdb::GridBase::Ptr readHeader(std::size_t index);
    // Metadata, transform and topology: nodes, value masks and tile values; leaf values are not
    // loaded and must not be read.
    openvdb::GridBase::Ptr readTopology(std::size_t index);
    // Everything, with leaf values only for leaves that overlap `clip` (index space); leaves
    // outside it are dropped. CoordBBox::inf() reads the whole grid.
    openvdb::GridBase::Ptr readRegion(std::size_t index, const openvdb::CoordBBox& clip);

    // For streaming a tree without building it (io/vdb_tree_stream.h): reads grid `index`'s
    // metadata and transform and leaves stream() at its topology, with the grid's decoding state
    // set until the next read. seekToBuffers() moves to the leaf values. Not for instances.
    openvdb::GridBase::Ptr openTree(std::size_t index);
    void seekToBuffers(std::size_t index);
    std::istream& stream() { return mStream; }

private:
    enum class Depth { Header, Topology, Region };
    openvdb::GridBase::Ptr read(std::size_t index, Depth depth, const openvdb::CoordBBox& clip);
    openvdb::GridBase::Ptr readGridStart(std::size_t index);
    std::size_t treeSource(std::size_t index) const;  // the grid whose tree an instance shares

    std::filesystem::path mPath;
    std::uint64_t mFileBytes = 0;
    std::uint32_t mFormatVersion = 0;
    std::ifstream mStream;
    openvdb::io::StreamMetadata::Ptr mStreamMetadata;      // file level
    openvdb::io::StreamMetadata::Ptr mGridStreamMetadata;  // the grid being read
    openvdb::MetaMap mFileMetadata;
    std::vector<Entry> mEntries;
    std::vector<openvdb::io::GridDescriptor> mDescriptors;
};

// Per-allocation ceiling while reading a file of `fileBytes`: nothing OpenVDB reads legitimately
// needs a single buffer larger than the file plus its largest node table.
std::uint64_t vdbSingleAllocationLimit(std::uint64_t fileBytes);

// Turns whatever reading a VDB file may throw into one line that names the file.
Error vdbError(const std::filesystem::path& path, const AllocationBudget* budget);

// Runs f() under an allocation budget of `budgetBytes` and converts failures into an Error that
// names the file. f returns Result<T> or Status.
template <typename F>
auto guardedVdbCall(const std::filesystem::path& path, std::uint64_t budgetBytes,
                    std::uint64_t fileBytes, F&& f) -> decltype(f()) {
    AllocationBudget budget(budgetBytes, vdbSingleAllocationLimit(fileBytes));
    try {
        return f();
    } catch (...) {
        return vdbError(path, &budget);
    }
}

// Bytes of a regular file; an Error for a missing, unreadable, non-regular or empty file.
Result<std::uint64_t> vdbFileBytes(const std::filesystem::path& path);

// Registers OpenVDB's grid types once; cheap to call again.
void initializeOpenVdb();

}  // namespace engine::io
