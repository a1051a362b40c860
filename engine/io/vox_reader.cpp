// MagicaVoxel .vox chunks (io/vox_reader.h). A cursor over the file's bytes checks every read
// against what remains of the current chunk; a failed check throws a BadVox that parseVox turns
// into one line naming the file and the offset.
#include "io/vox_reader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <set>

#include "core/quoted_string.h"

namespace engine::io {

namespace fs = std::filesystem;

namespace {

// MagicaVoxel's default palette (its file format document), 0xAABBGGRR, index 0 unused.
constexpr std::uint32_t kDefaultPalette[256] = {
    0x00000000, 0xffffffff, 0xffccffff, 0xff99ffff, 0xff66ffff, 0xff33ffff, 0xff00ffff, 0xffffccff,
    0xffccccff, 0xff99ccff, 0xff66ccff, 0xff33ccff, 0xff00ccff, 0xffff99ff, 0xffcc99ff, 0xff9999ff,
    0xff6699ff, 0xff3399ff, 0xff0099ff, 0xffff66ff, 0xffcc66ff, 0xff9966ff, 0xff6666ff, 0xff3366ff,
    0xff0066ff, 0xffff33ff, 0xffcc33ff, 0xff9933ff, 0xff6633ff, 0xff3333ff, 0xff0033ff, 0xffff00ff,
    0xffcc00ff, 0xff9900ff, 0xff6600ff, 0xff3300ff, 0xff0000ff, 0xffffffcc, 0xffccffcc, 0xff99ffcc,
    0xff66ffcc, 0xff33ffcc, 0xff00ffcc, 0xffffcccc, 0xffcccccc, 0xff99cccc, 0xff66cccc, 0xff33cccc,
    0xff00cccc, 0xffff99cc, 0xffcc99cc, 0xff9999cc, 0xff6699cc, 0xff3399cc, 0xff0099cc, 0xffff66cc,
    0xffcc66cc, 0xff9966cc, 0xff6666cc, 0xff3366cc, 0xff0066cc, 0xffff33cc, 0xffcc33cc, 0xff9933cc,
    0xff6633cc, 0xff3333cc, 0xff0033cc, 0xffff00cc, 0xffcc00cc, 0xff9900cc, 0xff6600cc, 0xff3300cc,
    0xff0000cc, 0xffffff99, 0xffccff99, 0xff99ff99, 0xff66ff99, 0xff33ff99, 0xff00ff99, 0xffffcc99,
    0xffcccc99, 0xff99cc99, 0xff66cc99, 0xff33cc99, 0xff00cc99, 0xffff9999, 0xffcc9999, 0xff999999,
    0xff669999, 0xff339999, 0xff009999, 0xffff6699, 0xffcc6699, 0xff996699, 0xff666699, 0xff336699,
    0xff006699, 0xffff3399, 0xffcc3399, 0xff993399, 0xff663399, 0xff333399, 0xff003399, 0xffff0099,
    0xffcc0099, 0xff990099, 0xff660099, 0xff330099, 0xff000099, 0xffffff66, 0xffccff66, 0xff99ff66,
    0xff66ff66, 0xff33ff66, 0xff00ff66, 0xffffcc66, 0xffcccc66, 0xff99cc66, 0xff66cc66, 0xff33cc66,
    0xff00cc66, 0xffff9966, 0xffcc9966, 0xff999966, 0xff669966, 0xff339966, 0xff009966, 0xffff6666,
    0xffcc6666, 0xff996666, 0xff666666, 0xff336666, 0xff006666, 0xffff3366, 0xffcc3366, 0xff993366,
    0xff663366, 0xff333366, 0xff003366, 0xffff0066, 0xffcc0066, 0xff990066, 0xff660066, 0xff330066,
    0xff000066, 0xffffff33, 0xffccff33, 0xff99ff33, 0xff66ff33, 0xff33ff33, 0xff00ff33, 0xffffcc33,
    0xffcccc33, 0xff99cc33, 0xff66cc33, 0xff33cc33, 0xff00cc33, 0xffff9933, 0xffcc9933, 0xff999933,
    0xff669933, 0xff339933, 0xff009933, 0xffff6633, 0xffcc6633, 0xff996633, 0xff666633, 0xff336633,
    0xff006633, 0xffff3333, 0xffcc3333, 0xff993333, 0xff663333, 0xff333333, 0xff003333, 0xffff0033,
    0xffcc0033, 0xff990033, 0xff660033, 0xff330033, 0xff000033, 0xffffff00, 0xffccff00, 0xff99ff00,
    0xff66ff00, 0xff33ff00, 0xff00ff00, 0xffffcc00, 0xffcccc00, 0xff99cc00, 0xff66cc00, 0xff33cc00,
    0xff00cc00, 0xffff9900, 0xffcc9900, 0xff999900, 0xff669900, 0xff339900, 0xff009900, 0xffff6600,
    0xffcc6600, 0xff996600, 0xff666600, 0xff336600, 0xff006600, 0xffff3300, 0xffcc3300, 0xff993300,
    0xff663300, 0xff333300, 0xff003300, 0xffff0000, 0xffcc0000, 0xff990000, 0xff660000, 0xff330000,
    0xff0000ee, 0xff0000dd, 0xff0000bb, 0xff0000aa, 0xff000088, 0xff000077, 0xff000055, 0xff000044,
    0xff000022, 0xff000011, 0xff00ee00, 0xff00dd00, 0xff00bb00, 0xff00aa00, 0xff008800, 0xff007700,
    0xff005500, 0xff004400, 0xff002200, 0xff001100, 0xffee0000, 0xffdd0000, 0xffbb0000, 0xffaa0000,
    0xff880000, 0xff770000, 0xff550000, 0xff440000, 0xff220000, 0xff110000, 0xffeeeeee, 0xffdddddd,
    0xffbbbbbb, 0xffaaaaaa, 0xff888888, 0xff777777, 0xff555555, 0xff444444, 0xff222222, 0xff111111};

struct BadVox {
    std::size_t offset;
    std::string message;
};

using Dict = std::map<std::string, std::string>;

// Reads little-endian values from bytes [pos, end) of the file.
class Cursor {
public:
    Cursor(std::span<const std::uint8_t> bytes, std::size_t pos, std::size_t end)
        : mBytes(bytes), mPos(pos), mEnd(end) {}

    std::size_t pos() const { return mPos; }
    std::size_t remaining() const { return mEnd - mPos; }
    [[noreturn]] void fail(std::string message) const { throw BadVox{mPos, std::move(message)}; }
    void need(std::size_t n, const char* what) const {
        if (n > remaining()) fail(fmt::format("{} needs {} bytes, {} left", what, n, remaining()));
    }
    std::int32_t i32(const char* what) {
        need(4, what);
        std::uint32_t v = std::uint32_t(mBytes[mPos]) | std::uint32_t(mBytes[mPos + 1]) << 8 |
                          std::uint32_t(mBytes[mPos + 2]) << 16 |
                          std::uint32_t(mBytes[mPos + 3]) << 24;
        mPos += 4;
        return std::int32_t(v);
    }
    // A count of items of at least `itemBytes` each that must fit in what remains.
    std::size_t count(const char* what, std::size_t itemBytes) {
        const std::size_t at = mPos;
        const std::int32_t n = i32(what);
        if (n < 0 || std::size_t(n) * itemBytes > remaining())
            throw BadVox{
                at, fmt::format("{} {} does not fit in the {} bytes left", what, n, remaining())};
        return std::size_t(n);
    }
    const std::uint8_t* bytes(std::size_t n, const char* what) {
        need(n, what);
        const std::uint8_t* p = mBytes.data() + mPos;
        mPos += n;
        return p;
    }
    std::string string(const char* what) {
        const std::size_t n = count(what, 1);
        const std::uint8_t* p = bytes(n, what);
        return std::string(reinterpret_cast<const char*>(p), n);
    }
    Dict dict(const char* what) {
        Dict d;
        const std::size_t n = count(what, 8);  // a pair holds at least two string sizes
        for (std::size_t i = 0; i < n; ++i) {
            std::string key = string("dictionary key");
            d[std::move(key)] = string("dictionary value");
        }
        return d;
    }

private:
    std::span<const std::uint8_t> mBytes;
    std::size_t mPos, mEnd;
};

bool parseInts(const std::string& text, int* out, int n) {
    const char* p = text.data();
    const char* end = p + text.size();
    for (int i = 0; i < n; ++i) {
        while (p < end && *p == ' ') ++p;
        auto [next, ec] = std::from_chars(p, end, out[i]);
        if (ec != std::errc()) return false;
        p = next;
    }
    while (p < end && *p == ' ') ++p;
    return p == end;
}

float parseFloat(const Dict& d, const char* key, const Cursor& c) {
    auto it = d.find(key);
    if (it == d.end()) return 0.0f;
    float v = 0.0f;
    const char* b = it->second.data();
    auto [next, ec] = std::from_chars(b, b + it->second.size(), v);
    if (ec != std::errc() || next != b + it->second.size() || !std::isfinite(v))
        c.fail(fmt::format("material {} '{}' is not a number", key, printableText(it->second)));
    return v;
}

bool hidden(const Dict& d) {
    auto it = d.find("_hidden");
    return it != d.end() && it->second == "1";
}

std::string nameOf(const Dict& d) {
    auto it = d.find("_name");
    return it == d.end() ? std::string() : it->second;
}

void addNode(VoxFile& file, int id, VoxNode node, const Cursor& c) {
    if (id < 0) c.fail(fmt::format("node id {} is negative", id));
    if (!file.nodes.emplace(id, std::move(node)).second)
        c.fail(fmt::format("node id {} appears twice", id));
}

// What every scene-graph node chunk (nTRN, nGRP, nSHP) starts with: its id and attributes.
int readNodeHeader(VoxNode& n, VoxNode::Kind kind, Cursor& c, std::size_t chunk) {
    n.kind = kind;
    n.offset = chunk;
    const int id = c.i32("node id");
    Dict attributes = c.dict("node attributes");
    n.hidden = hidden(attributes);
    n.name = nameOf(attributes);
    return id;
}

void readTransform(VoxFile& file, Cursor& c, std::size_t chunk) {
    VoxNode n;
    const int id = readNodeHeader(n, VoxNode::Kind::Transform, c, chunk);
    n.child = c.i32("child node id");
    c.i32("reserved id");
    n.layer = c.i32("layer id");
    const std::size_t frames = c.count("frame count", 4);
    if (frames == 0) c.fail("transform node without frames");
    for (std::size_t f = 0; f < frames; ++f) {
        Dict frame = c.dict("frame attributes");
        if (f > 0) continue;  // frame 0: the scene as MagicaVoxel shows it unanimated
        if (auto r = frame.find("_r"); r != frame.end()) {
            int bits = -1;
            if (!parseInts(r->second, &bits, 1) || !decodeVoxRotation(bits, n.rotation))
                c.fail(fmt::format("node {}: '_r' = '{}' is not a rotation", id,
                                   printableText(r->second)));
        }
        if (auto t = frame.find("_t"); t != frame.end()) {
            int v[3];
            if (!parseInts(t->second, v, 3))
                c.fail(fmt::format("node {}: '_t' = '{}' is not three integers", id,
                                   printableText(t->second)));
            // Kept well inside int range so that placement arithmetic cannot overflow.
            for (int a : v)
                if (a < -kVoxMaxTranslation || a > kVoxMaxTranslation)
                    c.fail(fmt::format("node {}: translation {} is out of range", id, a));
            n.translation = {v[0], v[1], v[2]};
        }
    }
    addNode(file, id, std::move(n), c);
}

void readGroup(VoxFile& file, Cursor& c, std::size_t chunk) {
    VoxNode n;
    const int id = readNodeHeader(n, VoxNode::Kind::Group, c, chunk);
    const std::size_t children = c.count("child count", 4);
    n.children.reserve(children);
    for (std::size_t i = 0; i < children; ++i) n.children.push_back(c.i32("child node id"));
    addNode(file, id, std::move(n), c);
}

void readShape(VoxFile& file, Cursor& c, std::size_t chunk) {
    VoxNode n;
    const int id = readNodeHeader(n, VoxNode::Kind::Shape, c, chunk);
    const std::size_t models = c.count("model count", 8);
    if (models == 0) c.fail("shape node without models");
    for (std::size_t i = 0; i < models; ++i) {
        const int model = c.i32("model id");
        c.dict("model attributes");
        if (i == 0) n.model = model;
    }
    addNode(file, id, std::move(n), c);
}

void readChunk(VoxFile& file, const std::string& id, Cursor& c, std::size_t chunk,
               glm::ivec3& pendingSize, bool& sizePending) {
    if (id == "SIZE") {
        if (sizePending) c.fail("SIZE chunk without its XYZI chunk");
        int s[3] = {c.i32("size x"), c.i32("size y"), c.i32("size z")};
        for (int v : s)
            if (v < 1 || v > kVoxMaxModelSize)
                c.fail(fmt::format("model size {} is outside 1..{}", v, kVoxMaxModelSize));
        pendingSize = {s[0], s[1], s[2]};
        sizePending = true;
    } else if (id == "XYZI") {
        if (!sizePending) c.fail("XYZI chunk without a SIZE chunk before it");
        sizePending = false;
        VoxModel m;
        m.size = pendingSize;
        const std::size_t n = c.count("voxel count", 4);
        const std::uint8_t* p = c.bytes(n * 4, "voxels");
        m.voxels.reserve(n);
        for (std::size_t i = 0; i < n; ++i, p += 4) {
            VoxVoxel v{p[0], p[1], p[2], p[3]};
            if (v.x >= m.size.x || v.y >= m.size.y || v.z >= m.size.z)
                throw BadVox{
                    c.pos() - (n - i) * 4,
                    fmt::format("voxel ({}, {}, {}) lies outside its model of {} x {} x {}", v.x,
                                v.y, v.z, m.size.x, m.size.y, m.size.z)};
            if (v.colour != 0) m.voxels.push_back(v);  // index 0 is empty in MagicaVoxel too
        }
        file.models.push_back(std::move(m));
    } else if (id == "RGBA") {
        const std::uint8_t* p = c.bytes(256 * 4, "palette");
        // Entry i of the chunk is colour index i + 1; the 256th entry has no index.
        for (int i = 0; i < 255; ++i)
            file.palette[std::size_t(i + 1)] =
                std::uint32_t(p[4 * i]) | std::uint32_t(p[4 * i + 1]) << 8 |
                std::uint32_t(p[4 * i + 2]) << 16 | std::uint32_t(p[4 * i + 3]) << 24;
        file.hasPalette = true;
    } else if (id == "nTRN") {
        readTransform(file, c, chunk);
    } else if (id == "nGRP") {
        readGroup(file, c, chunk);
    } else if (id == "nSHP") {
        readShape(file, c, chunk);
    } else if (id == "LAYR") {
        const int layer = c.i32("layer id");
        Dict attributes = c.dict("layer attributes");
        file.layers[layer] = VoxLayer{nameOf(attributes), hidden(attributes)};
    } else if (id == "MATL") {
        const int index = c.i32("material id");
        Dict properties = c.dict("material properties");
        if (index < 1 || index > 255)
            return;  // MagicaVoxel writes ids 0..255; 0 is empty, 256th unused
        VoxMaterial m;
        if (auto t = properties.find("_type"); t != properties.end()) m.type = t->second;
        m.emit = parseFloat(properties, "_emit", c);
        m.flux = parseFloat(properties, "_flux", c);
        file.materials[index] = m;
    } else {
        file.skippedChunks[id]++;
    }
}

}  // namespace

bool decodeVoxRotation(int bits, VoxRotation& out) {
    if (bits < 0 || bits > 127) return false;
    const int c0 = bits & 3, c1 = (bits >> 2) & 3;
    if (c0 > 2 || c1 > 2 || c0 == c1) return false;
    const int cols[3] = {c0, c1, 3 - c0 - c1};
    out.m.fill(0);
    for (int row = 0; row < 3; ++row)
        out.m[std::size_t(row * 3 + cols[row])] = (bits >> (4 + row)) & 1 ? -1 : 1;
    return true;
}

int encodeVoxRotation(const VoxRotation& r) {
    int bits = 0;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            const int v = r.m[std::size_t(row * 3 + col)];
            if (v == 0) continue;
            if (row < 2) bits |= col << (2 * row);
            if (v < 0) bits |= 1 << (4 + row);
        }
    return bits;
}

VoxRotation VoxRotation::then(const VoxRotation& outer) const {
    VoxRotation r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int s = 0;
            for (int k = 0; k < 3; ++k)
                s += outer.m[std::size_t(i * 3 + k)] * m[std::size_t(k * 3 + j)];
            r.m[std::size_t(i * 3 + j)] = s;
        }
    return r;
}

std::uint32_t voxDefaultPaletteColour(int index) { return kDefaultPalette[index & 255]; }

Result<VoxFile> parseVox(std::span<const std::uint8_t> bytes, std::string_view name) {
    VoxFile file;
    try {
        Cursor head(bytes, 0, bytes.size());
        const std::uint8_t* magic = head.bytes(4, "the 'VOX ' header");
        if (std::memcmp(magic, "VOX ", 4) != 0)
            head.fail("not a MagicaVoxel .vox file (no 'VOX ' header)");
        file.version = head.i32("version");
        const std::uint8_t* mainId = head.bytes(4, "the MAIN chunk");
        if (std::memcmp(mainId, "MAIN", 4) != 0) head.fail("the first chunk is not MAIN");
        const std::size_t mainContent = head.count("MAIN content size", 1);
        const std::int32_t mainChildren = head.i32("MAIN children size");
        head.bytes(mainContent, "MAIN content");
        if (mainChildren < 0 || std::size_t(mainChildren) > head.remaining())
            head.fail(fmt::format("MAIN children size {} does not fit in the {} bytes left",
                                  mainChildren, head.remaining()));

        Cursor children(bytes, head.pos(), head.pos() + std::size_t(mainChildren));
        glm::ivec3 pendingSize{0};
        bool sizePending = false;
        while (children.remaining() > 0) {
            const std::size_t chunk = children.pos();
            const std::uint8_t* idBytes = children.bytes(4, "chunk id");
            std::string id(reinterpret_cast<const char*>(idBytes), 4);
            const std::int32_t content = children.i32("chunk content size");
            const std::int32_t nested = children.i32("chunk children size");
            if (content < 0 || nested < 0 ||
                std::size_t(content) + std::size_t(nested) > children.remaining())
                throw BadVox{chunk,
                             fmt::format("chunk '{}' claims {} + {} bytes, {} left",
                                         printableText(id), content, nested, children.remaining())};
            Cursor c(bytes, children.pos(), children.pos() + std::size_t(content));
            readChunk(file, id, c, chunk, pendingSize, sizePending);
            children.bytes(std::size_t(content) + std::size_t(nested),
                           "chunk");  // trailing bytes and children ignored
        }
        if (sizePending) throw BadVox{children.pos(), "SIZE chunk without its XYZI chunk"};
    } catch (const BadVox& e) {
        return makeError("{}: offset {}: {}", name, e.offset, e.message);
    }
    if (!file.hasPalette)
        for (int i = 0; i < 256; ++i) file.palette[std::size_t(i)] = kDefaultPalette[i];
    return file;
}

Result<VoxFile> readVoxFile(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        return makeError("{}: cannot open: not a regular file", path.string());
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) return makeError("{}: cannot open: {}", path.string(), ec.message());
    if (size > (std::uintmax_t(1) << 31))
        return makeError("{}: {} bytes is too large for a .vox file", path.string(), size);
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        return makeError("{}: cannot read", path.string());
    return parseVox(bytes, path.string());
}

Result<std::vector<VoxInstance>> voxInstances(const VoxFile& file, std::string_view name) {
    std::vector<VoxInstance> out;
    if (file.nodes.empty()) {
        // No scene graph (files before MagicaVoxel 0.99): the models as stored, corner at the
        // origin.
        for (std::size_t i = 0; i < file.models.size(); ++i) {
            VoxInstance in;
            in.model = int(i);
            in.translation = file.models[i].size / 2;  // cancels the pivot
            out.push_back(in);
        }
        return out;
    }
    if (!file.nodes.count(0)) return makeError("{}: the scene graph has no root node 0", name);
    struct Frame {
        VoxRotation rotation;
        glm::ivec3 translation{0};
    };
    std::set<int> path;  // nodes on the way down: one seen again is a cycle
    std::string error;
    std::size_t visits =
        0;  // nodes may be shared (several transforms over one shape): bound the walk
    std::function<bool(int, const Frame&, int)> visit = [&](int id, const Frame& parent,
                                                            int depth) -> bool {
        auto it = file.nodes.find(id);
        if (it == file.nodes.end()) {
            error = fmt::format("{}: scene graph: node {} does not exist", name, id);
            return false;
        }
        const VoxNode& n = it->second;
        if (!path.insert(id).second) {
            error = fmt::format("{}: offset {}: scene graph: node {} is its own ancestor (a cycle)",
                                name, n.offset, id);
            return false;
        }
        if (depth > kVoxMaxGraphDepth || ++visits > 4 * kVoxMaxInstances) {
            error = fmt::format(
                "{}: offset {}: scene graph: more than {} levels deep or more than {} node visits",
                name, n.offset, kVoxMaxGraphDepth, 4 * kVoxMaxInstances);
            return false;
        }
        bool ok = true;
        if (!n.hidden) switch (n.kind) {
                case VoxNode::Kind::Transform: {
                    auto layer = file.layers.find(n.layer);
                    if (layer != file.layers.end() && layer->second.hidden) break;
                    // A child's frame inside its parent's: p -> parent(R p + t).
                    Frame f{n.rotation.then(parent.rotation),
                            parent.rotation.apply(n.translation) + parent.translation};
                    ok = visit(n.child, f, depth + 1);
                    break;
                }
                case VoxNode::Kind::Group:
                    for (int c : n.children)
                        if (!(ok = visit(c, parent, depth + 1))) break;
                    break;
                case VoxNode::Kind::Shape:
                    if (n.model < 0 || std::size_t(n.model) >= file.models.size()) {
                        error = fmt::format(
                            "{}: offset {}: shape node {} names model {}, the file has {}", name,
                            n.offset, id, n.model, file.models.size());
                        ok = false;
                    } else if (out.size() >= kVoxMaxInstances) {
                        error = fmt::format("{}: the scene graph places more than {} models", name,
                                            kVoxMaxInstances);
                        ok = false;
                    } else {
                        out.push_back({n.model, parent.rotation, parent.translation});
                    }
                    break;
            }
        path.erase(id);
        return ok;
    };
    if (!visit(0, Frame{}, 0)) return makeError("{}", error);
    return out;
}

}  // namespace engine::io
