// TreeStream: reads a standard OpenVDB tree (5-4-3) straight from a file stream without building
// it. Internal to engine/io.
//
// walk() parses the topology exactly as RootNode/InternalNode/LeafNode::readTopology() would,
// using OpenVDB's own mask and readCompressedValues() code, but owns everything it allocates and
// keeps nothing: it validates, measures what OpenVDB would allocate, and lists the root's
// children. stream() then walks the topology again in the order OpenVDB reads values (root
// children sorted by origin) while a second stream reads each leaf's values as its leaf comes
// up, so a whole grid passes through holding one leaf's values and one path of node masks.
//
// Uses: VdbReader walks every tree before OpenVDB reads it (OpenVDB 10 leaks or trusts damaged
// topology; see vdb_reader.cpp), and import streams a voxel-for-voxel copy of a grid into the
// world without ever building an OpenVDB tree.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <istream>
#include <memory>
#include <openvdb/openvdb.h>
#include <string>
#include <type_traits>
#include <vector>

namespace engine::io {

// What reading a tree with OpenVDB will allocate: nodes (leaves without values), and the values
// of the leaves a clip box reaches.
struct TreeBytes {
    std::uint64_t nodes = 0;
    std::uint64_t leafValues = 0;
};

template <typename TreeT>
class TreeStream {
public:
    using RootT = typename TreeT::RootNodeType;
    using ValueT = typename TreeT::ValueType;
    using LeafT = typename TreeT::LeafNodeType;
    using LeafMask = typename LeafT::NodeMaskType;
    using TileFn = std::function<void(const openvdb::CoordBBox&, const ValueT&, bool active)>;

    // Called for each leaf in value order: return true to receive its values (then onValues),
    // false to skip them.
    using LeafFn = std::function<bool(const openvdb::Coord& origin, const LeafMask& mask)>;
    using ValuesFn = std::function<void(const openvdb::Coord& origin, const LeafMask& mask,
                                        const ValueT* values)>;

    struct RootChild {
        openvdb::Coord origin;
        std::streamoff topology;  // where its subtree starts in the file
    };
    struct Root {
        ValueT background{};
        TreeBytes bytes;
        std::vector<RootChild> children;  // sorted by origin: the order values are stored in
    };

    // The stream must be at the tree's topology with the grid's stream state set (compression,
    // half-float, class). Reports the root's tiles (stream() reports the rest); tiles equal to
    // the background and inactive are not reported. Throws on damaged topology. A callback that
    // sets *stop ends the walk early (a partial Root), reading nothing more.
    static Root walk(std::istream& is, std::uint32_t version, bool fromHalf,
                     std::uint64_t fileBytes, const openvdb::CoordBBox* clip, const TileFn& tile,
                     const bool* stop = nullptr) {
        namespace vdb = openvdb;
        std::int32_t buffers =
            0;  // TreeBase::readTopology(): always 1 since OpenVDB 3 (it only warns otherwise)
        is.read(reinterpret_cast<char*>(&buffers), sizeof(buffers));
        if (buffers != 1)
            throw vdb::IoError("multi-buffer trees are not supported (" + std::to_string(buffers) +
                               " buffers)");
        Root root;
        ValueT& background = root.background;
        is.read(reinterpret_cast<char*>(&background), sizeof(ValueT));
        vdb::io::setGridBackgroundValuePtr(is, &background);
        struct ResetBackground {
            std::istream& is;
            ~ResetBackground() { vdb::io::setGridBackgroundValuePtr(is, nullptr); }
        } reset{is};
        vdb::Index tiles = 0, children = 0;
        is.read(reinterpret_cast<char*>(&tiles), sizeof(tiles));
        is.read(reinterpret_cast<char*>(&children), sizeof(children));
        const std::uint64_t remaining = fileBytes - std::uint64_t(is.tellg());
        const std::uint64_t tileBytes = 3 * sizeof(std::int32_t) + sizeof(ValueT) + sizeof(bool);
        if (std::uint64_t(tiles) * tileBytes + std::uint64_t(children) * 12 > remaining)
            throw std::ios_base::failure("root node counts run past the end of the file");

        // Root entries are keyed by origin: each must be aligned to its node size and, for
        // children, unique (OpenVDB overwrites a child with a later one of the same key and leaks
        // it).
        using ChildT = typename RootT::ChildNodeType;
        auto aligned = [](const std::int32_t v[3]) {
            return (v[0] & (ChildT::DIM - 1)) == 0 && (v[1] & (ChildT::DIM - 1)) == 0 &&
                   (v[2] & (ChildT::DIM - 1)) == 0;
        };
        TreeBytes& bytes = root.bytes;
        bytes.nodes = std::uint64_t(tiles) * 96;  // a std::map entry per root tile
        for (vdb::Index n = 0; n < tiles; ++n) {
            if (stop && *stop) return root;
            std::int32_t origin[3];
            ValueT value;
            bool active = false;
            is.read(reinterpret_cast<char*>(origin), sizeof(origin));
            is.read(reinterpret_cast<char*>(&value), sizeof(ValueT));
            is.read(reinterpret_cast<char*>(&active), sizeof(bool));
            if (!aligned(origin)) throw vdb::IoError("a root tile is not aligned to its node size");
            if (tile && (active || !vdb::math::isExactlyEqual(value, background)))
                tile(vdb::CoordBBox::createCube(vdb::Coord(origin[0], origin[1], origin[2]),
                                                ChildT::DIM),
                     value, active);
        }
        for (vdb::Index n = 0; n < children; ++n) {
            if (stop && *stop) return root;
            std::int32_t origin[3];
            is.read(reinterpret_cast<char*>(origin), sizeof(origin));
            if (!aligned(origin))
                throw vdb::IoError("a root child is not aligned to its node size");
            bytes.nodes += 96;
            RootChild child{vdb::Coord(origin[0], origin[1], origin[2]),
                            std::streamoff(is.tellg())};
            walkNode<ChildT>(is, version, fromHalf, child.origin, background, clip, TileFn(),
                             nullptr, bytes);
            root.children.push_back(child);
        }
        // OpenVDB reads values in the order of its root table (sorted by origin), which is the
        // order writers store children in; a damaged file may differ, so sort.
        std::sort(root.children.begin(), root.children.end(),
                  [](const RootChild& a, const RootChild& b) { return a.origin < b.origin; });
        for (std::size_t i = 1; i < root.children.size(); ++i)
            if (root.children[i].origin == root.children[i - 1].origin)
                throw vdb::IoError("two root children share an origin");
        return root;
    }

    // Walks the internal nodes again, in value order, reading each wanted leaf's values from
    // `values` (positioned at the grid's buffers, with the same stream state as `topology`).
    // Tiles below the root are reported here (root tiles were reported by walk()).
    // `values` may be null when no leaf is wanted (a walk for the leaves' masks only). A callback
    // that sets *stop ends the walk at the next node, reading nothing more.
    static void stream(std::istream& topology, std::istream* values, std::uint32_t version,
                       bool fromHalf, const Root& root, const TileFn& tile, const LeafFn& wanted,
                       const ValuesFn& onValues, const bool* stop = nullptr) {
        namespace vdb = openvdb;
        vdb::io::setGridBackgroundValuePtr(topology, &root.background);
        if (values) vdb::io::setGridBackgroundValuePtr(*values, &root.background);
        struct ResetBackground {
            std::istream& a;
            std::istream* b;
            ~ResetBackground() {
                vdb::io::setGridBackgroundValuePtr(a, nullptr);
                if (b) vdb::io::setGridBackgroundValuePtr(*b, nullptr);
            }
        } reset{topology, values};
        std::unique_ptr<ValueT[]> buffer(new ValueT[LeafT::SIZE]);
        LeafVisit visit{values, fromHalf, wanted, onValues, buffer.get(), stop};
        TreeBytes unused;
        for (const RootChild& child : root.children) {
            if (visit.stopped()) return;
            topology.seekg(child.topology);
            walkNode<typename RootT::ChildNodeType>(topology, version, fromHalf, child.origin,
                                                    root.background, nullptr, tile, &visit, unused);
        }
    }

private:
    // Reads (or skips) each leaf's record in the buffer section as the walk reaches the leaf.
    struct LeafVisit {
        std::istream* values;
        bool fromHalf;
        const LeafFn& wanted;
        const ValuesFn& onValues;
        ValueT* buffer;
        const bool* stop;

        bool stopped() const { return stop && *stop; }

        void operator()(const openvdb::Coord& origin, const LeafMask& mask) const {
            const bool want = wanted(origin, mask);
            if (!values) return;
            values->seekg(std::streamoff(mask.memUsage()),
                          std::ios_base::cur);  // the stored copy of the mask
            if (want) {
                openvdb::io::readCompressedValues(*values, buffer, LeafT::SIZE, mask, fromHalf);
                onValues(origin, mask, buffer);
            } else {
                openvdb::io::readCompressedValues<ValueT, LeafMask>(*values, nullptr, LeafT::SIZE,
                                                                    mask, fromHalf);
            }
        }
    };

    template <typename NodeT>
    static void walkNode(std::istream& is, std::uint32_t version, bool fromHalf,
                         const openvdb::Coord& origin, const ValueT& background,
                         const openvdb::CoordBBox* clip, const TileFn& tile,
                         const LeafVisit* leaves, TreeBytes& bytes) {
        namespace vdb = openvdb;
        typename NodeT::NodeMaskType valueMask;
        bytes.nodes += sizeof(NodeT) + 16;  // the node and malloc's header
        if constexpr (NodeT::LEVEL == 0) {
            valueMask.load(is);
            constexpr bool inlineValues =
                std::is_same_v<ValueT, bool>;  // bool and mask leaves are bit sets
            if (!inlineValues && clip &&
                clip->hasOverlap(vdb::CoordBBox::createCube(origin, NodeT::DIM)))
                bytes.leafValues += NodeT::SIZE * sizeof(ValueT) + 16;
            if (leaves) (*leaves)(origin, valueMask);
        } else {
            using ChildT = typename NodeT::ChildNodeType;
            typename NodeT::NodeMaskType childMask;
            childMask.load(is);
            valueMask.load(is);
            const bool oldVersion = version < vdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION;
            const vdb::Index count = oldVersion ? childMask.countOff() : NodeT::NUM_VALUES;
            std::unique_ptr<ValueT[]> values(new ValueT[count]);
            vdb::io::readCompressedValues(is, values.get(), count, valueMask, fromHalf);
            auto childOrigin = [&](vdb::Index pos) {
                vdb::Coord local;
                NodeT::offsetToLocalCoord(pos, local);
                return origin + (local << ChildT::TOTAL);
            };
            if (tile) {
                // Values are stored for every entry (or, in old files, for every non-child one).
                for (vdb::Index pos = 0, v = 0; pos < NodeT::NUM_VALUES; ++pos) {
                    if (childMask.isOn(pos)) {
                        if (!oldVersion) ++v;
                        continue;
                    }
                    const ValueT& value = values[oldVersion ? v++ : pos];
                    const bool active = valueMask.isOn(pos);
                    if (!oldVersion) ++v;
                    if (active || !vdb::math::isExactlyEqual(value, background))
                        tile(vdb::CoordBBox::createCube(childOrigin(pos), ChildT::DIM), value,
                             active);
                }
            }
            values.reset();
            for (auto it = childMask.beginOn(); it; ++it) {
                if (leaves && leaves->stopped()) return;
                walkNode<ChildT>(is, version, fromHalf, childOrigin(it.pos()), background, clip,
                                 tile, leaves, bytes);
            }
        }
    }
};

}  // namespace engine::io
