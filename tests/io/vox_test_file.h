// Helpers for the .vox tests, written apart from engine/io/vox_*: a builder that writes .vox
// bytes chunk by chunk (so tests can make files MagicaVoxel would, and damaged ones), and an
// independent count of the voxels a file shows (its visible model instances), to check the
// import against.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace vox_test {

using Bytes = std::vector<std::uint8_t>;
using Dict = std::vector<std::pair<std::string, std::string>>;

inline void putI32(Bytes& b, std::int32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(std::uint8_t(std::uint32_t(v) >> (8 * i)));
}
inline void putString(Bytes& b, const std::string& s) {
    putI32(b, std::int32_t(s.size()));
    b.insert(b.end(), s.begin(), s.end());
}
inline void putDict(Bytes& b, const Dict& d) {
    putI32(b, std::int32_t(d.size()));
    for (const auto& [k, v] : d) putString(b, k), putString(b, v);
}

struct VoxBuilder {
    Bytes children;

    void chunk(const char* id, const Bytes& content) {
        children.insert(children.end(), id, id + 4);
        putI32(children, std::int32_t(content.size()));
        putI32(children, 0);
        children.insert(children.end(), content.begin(), content.end());
    }
    struct V {
        int x, y, z, colour;
    };
    void model(int sx, int sy, int sz, const std::vector<V>& voxels) {
        Bytes size, xyzi;
        putI32(size, sx), putI32(size, sy), putI32(size, sz);
        chunk("SIZE", size);
        putI32(xyzi, std::int32_t(voxels.size()));
        for (const V& v : voxels)
            for (int c : {v.x, v.y, v.z, v.colour}) xyzi.push_back(std::uint8_t(c));
        chunk("XYZI", xyzi);
    }
    void transform(int id, int child, int layer, const Dict& frame, const Dict& attributes = {}) {
        Bytes b;
        putI32(b, id), putDict(b, attributes), putI32(b, child), putI32(b, -1), putI32(b, layer),
            putI32(b, 1);
        putDict(b, frame);
        chunk("nTRN", b);
    }
    void group(int id, const std::vector<int>& kids, const Dict& attributes = {}) {
        Bytes b;
        putI32(b, id), putDict(b, attributes), putI32(b, std::int32_t(kids.size()));
        for (int k : kids) putI32(b, k);
        chunk("nGRP", b);
    }
    void shape(int id, int model, const Dict& attributes = {}) {
        Bytes b;
        putI32(b, id), putDict(b, attributes), putI32(b, 1), putI32(b, model), putDict(b, {});
        chunk("nSHP", b);
    }
    void layer(int id, bool hidden) {
        Bytes b;
        putI32(b, id), putDict(b, hidden ? Dict{{"_hidden", "1"}} : Dict{}), putI32(b, -1);
        chunk("LAYR", b);
    }
    // colours[i]: colour index i + 1, 0xAABBGGRR.
    void palette(const std::vector<std::uint32_t>& colours) {
        Bytes b;
        for (int i = 0; i < 256; ++i)
            putI32(b,
                   std::int32_t(i < int(colours.size()) ? colours[std::size_t(i)] : 0xFF000000u));
        chunk("RGBA", b);
    }
    void material(int index, const Dict& properties) {
        Bytes b;
        putI32(b, index), putDict(b, properties);
        chunk("MATL", b);
    }
    Bytes bytes() const {
        Bytes b{'V', 'O', 'X', ' '};
        putI32(b, 150);
        b.insert(b.end(), {'M', 'A', 'I', 'N'});
        putI32(b, 0);
        putI32(b, std::int32_t(children.size()));
        b.insert(b.end(), children.begin(), children.end());
        return b;
    }
    void write(const std::filesystem::path& path) const { writeBytes(path, bytes()); }
    static void writeBytes(const std::filesystem::path& path, const Bytes& b) {
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
    }
};

// The voxels a valid file shows: the sum, over the visible shape nodes reached from node 0
// (or over all models when there is no scene graph), of their model's XYZI voxels.
inline std::uint64_t countVisibleVoxels(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    Bytes d((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto i32 = [&](std::size_t& o) {
        std::int32_t v;
        std::memcpy(&v, d.data() + o, 4);
        o += 4;
        return v;
    };
    auto dict = [&](std::size_t& o) {
        std::map<std::string, std::string> r;
        for (int n = i32(o); n > 0; --n) {
            int kl = i32(o);
            std::string k(reinterpret_cast<const char*>(d.data() + o), std::size_t(kl));
            o += std::size_t(kl);
            int vl = i32(o);
            r[k] = std::string(reinterpret_cast<const char*>(d.data() + o), std::size_t(vl));
            o += std::size_t(vl);
        }
        return r;
    };
    std::vector<std::uint64_t> modelVoxels;
    struct Node {
        char kind;
        bool hidden;
        int layer;
        std::vector<int> next;  // child(ren), or the model for a shape
    };
    std::map<int, Node> nodes;
    std::set<int> hiddenLayers;
    std::size_t p = 20;
    while (p + 12 <= d.size()) {
        std::string id(reinterpret_cast<const char*>(d.data() + p), 4);
        std::size_t o = p + 4;
        const std::size_t n = std::size_t(i32(o));
        i32(o);
        const std::size_t end = o + n;
        if (id == "XYZI") {
            std::uint64_t count = 0;
            for (int k = i32(o), i = 0; i < k; ++i)
                if (d[o + 4 * std::size_t(i) + 3] != 0) ++count;
            modelVoxels.push_back(count);
        } else if (id == "nTRN" || id == "nGRP" || id == "nSHP") {
            const int nodeId = i32(o);
            Node node{id[1], dict(o)["_hidden"] == "1", -1, {}};
            if (id == "nTRN") {
                node.next.push_back(i32(o));
                i32(o);
                node.layer = i32(o);
            } else if (id == "nGRP") {
                for (int k = i32(o); k > 0; --k) node.next.push_back(i32(o));
            } else {
                i32(o);
                node.next.push_back(i32(o));
            }
            nodes[nodeId] = node;
        } else if (id == "LAYR") {
            const int layer = i32(o);
            if (dict(o)["_hidden"] == "1") hiddenLayers.insert(layer);
        }
        p = end;
    }
    if (nodes.empty()) {
        std::uint64_t all = 0;
        for (std::uint64_t v : modelVoxels) all += v;
        return all;
    }
    std::uint64_t total = 0;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        const Node& node = nodes.at(stack.back());
        stack.pop_back();
        if (node.hidden || hiddenLayers.count(node.layer)) continue;
        if (node.kind == 'S')
            total += modelVoxels.at(std::size_t(node.next[0]));
        else
            stack.insert(stack.end(), node.next.begin(), node.next.end());
    }
    return total;
}

}  // namespace vox_test
