// MagicaVoxel .vox export (io/vox_export.h): count the materials in use, give each a palette
// index (exactly, or through the colour quantiser), cut the content into <= 256^3 models and
// write the chunks with a scene graph that puts each model back where it was.
#include "io/vox_export.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>
#include <map>
#include <tuple>

#include "core/atomic_file.h"
#include "io/colour_quantizer.h"
#include "io/vox_import.h"
#include "io/vox_reader.h"
#include "world/solid_voxels.h"

namespace engine::io {

namespace fs = std::filesystem;

namespace {

constexpr int kVoxPaletteColours = 255;

// The palette: index (1..255) per material id, colours and emission per index.
struct VoxPalette {
    std::vector<std::uint8_t> index;  // by material id; 0 for unused
    std::array<std::uint32_t, 256> colour{};
    std::array<float, 256> strength{};
    int used = 0;
};

VoxPalette buildPalette(const world::Scene& scene, const std::vector<std::uint64_t>& counts,
                        VoxExportReport& r) {
    const auto& materials = scene.palette.materials();
    VoxPalette p;
    p.index.assign(materials.size(), 0);
    // Exact when the (colour, emission) pairs fit: each pair one index, in material order.
    std::map<std::pair<std::uint32_t, float>, int> pairs;
    std::vector<std::pair<std::uint32_t, float>> order;
    for (std::size_t m = 1; m < materials.size(); ++m) {
        if (!counts[m]) continue;
        const world::Material& mat = materials[m];
        auto key = std::make_pair(voxColourFromLinear(mat.albedo),
                                  mat.emissive() ? mat.emissionStrength : 0.0f);
        if (pairs.emplace(key, 0).second) order.push_back(key);
        if (mat.emissive() && mat.emissionColor != mat.albedo) r.emissionColourDiffers += counts[m];
    }
    if (order.size() <= std::size_t(kVoxPaletteColours)) {
        for (std::size_t i = 0; i < order.size(); ++i) {
            pairs[order[i]] = int(i + 1);
            p.colour[i + 1] = order[i].first;
            p.strength[i + 1] = order[i].second;
        }
        for (std::size_t m = 1; m < materials.size(); ++m) {
            if (!counts[m]) continue;
            const world::Material& mat = materials[m];
            p.index[m] = std::uint8_t(pairs.at(
                {voxColourFromLinear(mat.albedo), mat.emissive() ? mat.emissionStrength : 0.0f}));
        }
        p.used = int(order.size());
        return p;
    }
    // Too many: quantise the albedos; an index emits when most of its voxels do, with their mean
    // strength.
    r.quantised = true;
    ColourHistogram histogram;
    for (std::size_t m = 1; m < materials.size(); ++m)
        if (counts[m]) histogram.add(clampAlbedo(materials[m].albedo), counts[m]);
    ColourMapper mapper(quantizeColours(histogram, kVoxPaletteColours));
    ColourError error;
    std::array<std::uint64_t, 256> voxels{}, emissiveVoxels{};
    std::array<double, 256> strengthSum{};
    for (std::size_t m = 1; m < materials.size(); ++m) {
        if (!counts[m]) continue;
        const world::Material& mat = materials[m];
        const int i = mapper.nearest(clampAlbedo(mat.albedo)) + 1;
        p.index[m] = std::uint8_t(i);
        error.add(
            double(glm::distance(clampAlbedo(mat.albedo), mapper.palette()[std::size_t(i - 1)])),
            counts[m]);
        voxels[std::size_t(i)] += counts[m];
        if (mat.emissive()) {
            emissiveVoxels[std::size_t(i)] += counts[m];
            strengthSum[std::size_t(i)] += double(mat.emissionStrength) * double(counts[m]);
        }
    }
    for (std::size_t i = 0; i < mapper.palette().size(); ++i) {
        p.colour[i + 1] = voxColourFromLinear(mapper.palette()[i]);
        const std::size_t k = i + 1;
        if (emissiveVoxels[k] * 2 > voxels[k])
            p.strength[k] = float(strengthSum[k] / double(emissiveVoxels[k]));
    }
    p.used = int(mapper.palette().size());
    r.meanColourError = error.mean();
    r.maxColourError = error.max;
    // Voxels that land on a colour or emission other than their own.
    for (std::size_t m = 1; m < materials.size(); ++m) {
        if (!counts[m]) continue;
        const world::Material& mat = materials[m];
        const std::size_t i = p.index[m];
        if (p.colour[i] != voxColourFromLinear(mat.albedo) ||
            p.strength[i] != (mat.emissive() ? mat.emissionStrength : 0.0f))
            r.changedVoxels += counts[m];
    }
    return p;
}

// Little-endian chunk writer.
struct Bytes {
    std::vector<std::uint8_t> data;
    void i32(std::int32_t v) {
        for (int i = 0; i < 4; ++i) data.push_back(std::uint8_t(std::uint32_t(v) >> (8 * i)));
    }
    void raw(const void* p, std::size_t n) {
        const auto* b = static_cast<const std::uint8_t*>(p);
        data.insert(data.end(), b, b + n);
    }
    void string(const std::string& s) {
        i32(std::int32_t(s.size()));
        raw(s.data(), s.size());
    }
    void dict(const std::vector<std::pair<std::string, std::string>>& d) {
        i32(std::int32_t(d.size()));
        for (const auto& [k, v] : d) string(k), string(v);
    }
    void chunk(const char id[4], const Bytes& content) {
        raw(id, 4);
        i32(std::int32_t(content.data.size()));
        i32(0);
        raw(content.data.data(), content.data.size());
    }
};

struct Model {
    glm::ivec3 origin{0};  // MagicaVoxel axes, within the content box
    glm::ivec3 size{0};
    std::vector<VoxVoxel> voxels;
};

// The models by (z, y, x) of their place in the content box, the order they are written in.
using Models = std::map<std::tuple<int, int, int>, Model>;

// The content box cut into models of at most kVoxMaxModelSize a side, each holding its voxels
// as palette indices. Engine (X, Y, Z) -> MagicaVoxel (X, maxZ - 1 - Z, Y), relative to the
// content box: the inverse of the import's (x, y, z) -> (x, z, -y) up to the shift the import
// applies.
Models cutIntoModels(const world::BrickGrid& grid, const world::Box& content,
                     const VoxPalette& palette, bool empty) {
    const glm::ivec3 extent = content.size();
    const glm::ivec3 mvExtent(extent.x, extent.z, extent.y);
    Models models;
    auto modelAt = [&](glm::ivec3 mv) -> Model& {
        const glm::ivec3 chunk = mv / kVoxMaxModelSize;
        Model& m = models[{chunk.z, chunk.y, chunk.x}];
        if (m.size.x == 0) {
            m.origin = chunk * kVoxMaxModelSize;
            m.size = glm::min(mvExtent - m.origin, glm::ivec3(kVoxMaxModelSize));
        }
        return m;
    };
    if (empty) modelAt(glm::ivec3(0));  // MagicaVoxel wants at least one model
    world::forEachSolidVoxel(grid, [&](glm::ivec3 p, world::MaterialId id) {
        const glm::ivec3 q = p - content.min;
        const glm::ivec3 mv(q.x, extent.z - 1 - q.z, q.y);
        Model& m = modelAt(mv);
        const glm::ivec3 local = mv - m.origin;
        m.voxels.push_back({std::uint8_t(local.x), std::uint8_t(local.y), std::uint8_t(local.z),
                            palette.index[id]});
    });
    return models;
}

// SIZE and XYZI of every model; each model's voxels are freed once written.
void writeModels(Models& models, Bytes& children) {
    for (auto& [key, m] : models) {
        Bytes size, xyzi;
        size.i32(m.size.x), size.i32(m.size.y), size.i32(m.size.z);
        children.chunk("SIZE", size);
        xyzi.i32(std::int32_t(m.voxels.size()));
        xyzi.raw(m.voxels.data(), m.voxels.size() * sizeof(VoxVoxel));
        children.chunk("XYZI", xyzi);
        std::vector<VoxVoxel>().swap(m.voxels);  // written: free it before the next model's copy
    }
}

// Scene graph: root transform 0 -> group 1 -> (transform 2 + 2i -> shape 3 + 2i -> model i),
// then the one layer.
void writeSceneGraph(const Models& models, Bytes& children) {
    Bytes root, group;
    root.i32(0), root.dict({}), root.i32(1), root.i32(-1), root.i32(-1), root.i32(1), root.dict({});
    children.chunk("nTRN", root);
    group.i32(1), group.dict({}), group.i32(std::int32_t(models.size()));
    for (std::size_t i = 0; i < models.size(); ++i) group.i32(std::int32_t(2 + 2 * i));
    children.chunk("nGRP", group);
    std::size_t i = 0;
    for (const auto& [key, m] : models) {
        // The import places voxel v at v - size / 2 + _t: _t = origin + size / 2 puts it at
        // origin + v.
        const glm::ivec3 t = m.origin + m.size / 2;
        Bytes transform, shape;
        transform.i32(std::int32_t(2 + 2 * i)), transform.dict({}),
            transform.i32(std::int32_t(3 + 2 * i));
        transform.i32(-1), transform.i32(0), transform.i32(1);
        transform.dict({{"_t", fmt::format("{} {} {}", t.x, t.y, t.z)}});
        children.chunk("nTRN", transform);
        shape.i32(std::int32_t(3 + 2 * i)), shape.dict({}), shape.i32(1),
            shape.i32(std::int32_t(i)), shape.dict({});
        children.chunk("nSHP", shape);
        ++i;
    }
    Bytes layer;
    layer.i32(0), layer.dict({}), layer.i32(-1);
    children.chunk("LAYR", layer);
}

// RGBA, and a MATL for every index that emits. Returns how many emit.
int writePalette(const VoxPalette& palette, Bytes& children) {
    // Entry k is colour index k + 1; indices the export does not use keep MagicaVoxel's
    // defaults.
    Bytes rgba;
    for (int k = 1; k <= 256; ++k) {
        const std::uint32_t c =
            k <= palette.used ? palette.colour[std::size_t(k)] : voxDefaultPaletteColour(k & 255);
        rgba.i32(std::int32_t(c));
    }
    children.chunk("RGBA", rgba);
    int emissive = 0;
    for (int k = 1; k <= palette.used; ++k) {
        if (palette.strength[std::size_t(k)] <= 0.0f) continue;
        float emit = 0.0f, flux = 0.0f;
        voxEmitFlux(palette.strength[std::size_t(k)], emit, flux);
        Bytes matl;
        matl.i32(k);
        matl.dict({{"_type", "_emit"},
                   {"_emit", fmt::format("{}", emit)},
                   {"_flux", fmt::format("{}", flux)}});
        children.chunk("MATL", matl);
        ++emissive;
    }
    return emissive;
}

}  // namespace

Status exportVox(const world::Scene& scene, const fs::path& path, VoxExportReport* reportOut) {
    VoxExportReport r;
    const world::BrickGrid& grid = scene.grid;
    std::vector<std::uint64_t> counts(scene.palette.size(), 0);
    world::Box content{glm::ivec3(INT32_MAX), glm::ivec3(INT32_MIN)};
    world::forEachSolidVoxel(grid, [&](glm::ivec3 p, world::MaterialId m) {
        counts[m]++;
        content.min = glm::min(content.min, p);
        content.max = glm::max(content.max, p + 1);
        r.solidVoxels++;
    });
    if (r.solidVoxels == 0) content = {glm::ivec3(0), glm::ivec3(1)};
    const VoxPalette palette = buildPalette(scene, counts, r);
    Models models = cutIntoModels(grid, content, palette, r.solidVoxels == 0);

    Bytes children;
    writeModels(models, children);
    writeSceneGraph(models, children);
    r.emissive = writePalette(palette, children);
    if (children.data.size() > 0x7FFFFFF0u)
        return makeError("{}: the world's {} voxels do not fit in one .vox file (2 GiB)",
                         path.string(), r.solidVoxels);
    Bytes header;
    header.data.reserve(20);  // the five fields below (and GCC 12 then sees no overflow)
    header.raw("VOX ", 4);
    header.i32(150);
    header.raw("MAIN", 4);
    header.i32(0);
    header.i32(std::int32_t(children.data.size()));

    Status s = writeFileAtomically(path, [&](AtomicFile& file) -> Status {
        if (Status w = file.write(header.data.data(), header.data.size()); !w) return w;
        return file.write(children.data.data(), children.data.size());
    });
    if (!s) return s;
    r.models = models.size();
    r.colours = palette.used;
    r.fileBytes = header.data.size() + children.data.size();
    if (reportOut) *reportOut = r;
    return {};
}

}  // namespace engine::io
