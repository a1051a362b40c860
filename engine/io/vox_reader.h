// MagicaVoxel .vox reader (docs/VOX.md): the chunk format of MagicaVoxel's file format document
// and its scene-graph extension — SIZE/XYZI models, the RGBA palette (the default one when
// absent), nTRN/nGRP/nSHP scene graph, LAYR layers and MATL materials. Other chunks are skipped.
//
// Every count and size is checked against the bytes that remain before anything is read or
// allocated, so a damaged file fails with one line naming the file and the byte offset.
// voxInstances() then walks the scene graph to the visible, placed models.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace engine::io {

inline constexpr int kVoxMaxModelSize =
    256;  // MagicaVoxel's limit per axis (XYZI coordinates are bytes)

struct VoxVoxel {
    std::uint8_t x, y, z, colour;  // colour: palette index 1..255
};

struct VoxModel {
    glm::ivec3 size{0};
    std::vector<VoxVoxel> voxels;
};

// A rotation that only permutes axes and flips signs: row-major, each row one +-1 entry.
struct VoxRotation {
    std::array<int, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};
    glm::ivec3 apply(glm::ivec3 v) const {
        return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
                m[6] * v.x + m[7] * v.y + m[8] * v.z};
    }
    VoxRotation then(const VoxRotation& outer) const;  // outer * this
    bool operator==(const VoxRotation&) const = default;
};

// The _r byte: bits 0-1 and 2-3 the column of row 0's and row 1's non-zero entry, bits 4-6 the
// signs of rows 0-2. False for a byte that is not a rotation (equal or out-of-range columns).
bool decodeVoxRotation(int bits, VoxRotation& out);
int encodeVoxRotation(const VoxRotation& r);

struct VoxNode {
    enum class Kind { Transform, Group, Shape };
    Kind kind = Kind::Transform;
    bool hidden = false;
    std::string name;
    // Transform: its child, layer and frame 0's rotation and translation.
    int child = -1;
    int layer = -1;
    VoxRotation rotation;
    glm::ivec3 translation{0};
    std::vector<int> children;  // group
    int model = -1;             // shape: frame 0's model
    std::size_t offset = 0;     // of its chunk, for messages
};

struct VoxLayer {
    std::string name;
    bool hidden = false;
};

// MATL: what the import uses; `type` is "_diffuse", "_metal", "_glass", "_emit", ...
struct VoxMaterial {
    std::string type;
    float emit = 0.0f;  // _emit, 0..1
    float flux = 0.0f;  // _flux, 0..4 (MagicaVoxel's "power")
};

struct VoxFile {
    int version = 0;
    std::vector<VoxModel> models;
    std::array<std::uint32_t, 256>
        palette{};            // [i] = colour index i, 0xAABBGGRR (R in the low byte)
    bool hasPalette = false;  // false: MagicaVoxel's default palette
    std::map<int, VoxNode> nodes;
    std::map<int, VoxLayer> layers;
    std::map<int, VoxMaterial> materials;  // by colour index
    std::map<std::string, int> skippedChunks;
};

std::uint32_t voxDefaultPaletteColour(int index);

// `name` prefixes every error message (the file's path).
Result<VoxFile> parseVox(std::span<const std::uint8_t> bytes, std::string_view name);
Result<VoxFile> readVoxFile(const std::filesystem::path& path);

// One visible model placed in MagicaVoxel's (Z-up) space: its voxel v lands on
// floor(rotation * (v + 0.5 - size / 2) + translation), size / 2 not rounded. Along an axis of
// even size the point is a voxel centre; along an odd one it is a whole number, and floor keeps
// an odd model's middle voxel in place when it is turned, as MagicaVoxel does.
struct VoxInstance {
    int model = 0;
    VoxRotation rotation;
    glm::ivec3 translation{0};
};

inline constexpr std::size_t kVoxMaxInstances = 1u << 18;
inline constexpr int kVoxMaxGraphDepth = 64;
// |_t| per axis; with the depth limit, sums of translations stay far from int overflow.
inline constexpr int kVoxMaxTranslation = 1 << 20;

// The visible instances, walking the scene graph from node 0 (hidden nodes and layers are
// skipped). Without a scene graph every model is one instance at the origin, untransformed.
// Fails on cycles, unknown node or model ids, and more than kVoxMaxInstances instances.
Result<std::vector<VoxInstance>> voxInstances(const VoxFile& file, std::string_view name);

// Where voxel v of a model of `size` lands under an instance (MagicaVoxel's Z-up space).
inline glm::ivec3 voxPlace(const VoxInstance& in, glm::ivec3 size, glm::ivec3 v) {
    // In half voxels, so the rotation stays in integers; >> 1 rounds down (arithmetic shift).
    const glm::ivec3 twice = in.rotation.apply(2 * v + 1 - size) + 2 * in.translation;
    return {twice.x >> 1, twice.y >> 1, twice.z >> 1};
}

}  // namespace engine::io
