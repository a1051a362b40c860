#include "world/region_codec.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <zstd.h>

#include "core/check.h"

namespace engine::world {

static_assert(std::endian::native == std::endian::little,
              "the region payload is written as the machine's bytes: little-endian only");

namespace {

constexpr std::uint32_t kMagic = 0x47525856u;  // "VXRG"
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderWords = 6;

void put(std::vector<std::uint8_t>& out, const void* data, std::size_t bytes) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    out.insert(out.end(), p, p + bytes);
}

}  // namespace

bool RegionSnapshot::empty() const {
    return std::all_of(cells.begin(), cells.end(),
                       [](std::uint32_t c) { return c == shared::CELL_EMPTY; });
}

RegionSnapshot snapshotRegion(const BrickGrid& grid, RegionKey key, int regionCellCount) {
    const CellRange range = regionCells(key, grid.sizeInCells(), regionCellCount);
    RegionSnapshot s;
    s.key = key;
    s.size = glm::max(range.size(), glm::ivec3(0));
    s.cells.reserve(range.count());
    for (int z = range.min.z; z < range.max.z; ++z)
        for (int y = range.min.y; y < range.max.y; ++y)
            for (int x = range.min.x; x < range.max.x; ++x) {
                const std::uint32_t c = grid.cell({x, y, z});
                if (!BrickGrid::cellIsBrick(c)) {
                    s.cells.push_back(c);
                    continue;
                }
                s.bricks.push_back(grid.brickVoxels(BrickGrid::cellBrick(c)));
                s.cells.push_back(static_cast<std::uint32_t>(s.bricks.size()));
            }
    return s;
}

void writeRegion(const RegionSnapshot& region, BrickGrid& grid, int regionCellCount,
                 glm::ivec3 cellOffset) {
    const glm::ivec3 lo = region.key.vec() * regionCellCount - cellOffset;
    std::size_t i = 0;
    for (int z = 0; z < region.size.z; ++z)
        for (int y = 0; y < region.size.y; ++y)
            for (int x = 0; x < region.size.x; ++x, ++i) {
                const glm::ivec3 c = lo + glm::ivec3(x, y, z);
                const std::uint32_t v = region.cells[i];
                if (v == shared::CELL_EMPTY || !grid.containsCell(c)) continue;
                if (BrickGrid::cellIsBrick(v))
                    grid.writeCell(c, region.bricks[v - 1u]);
                else
                    grid.writeCellUniform(c, BrickGrid::cellMaterial(v));
            }
}

void eraseRegion(BrickGrid& grid, RegionKey key, int regionCellCount) {
    const CellRange range = regionCells(key, grid.sizeInCells(), regionCellCount);
    for (int z = range.min.z; z < range.max.z; ++z)
        for (int y = range.min.y; y < range.max.y; ++y)
            for (int x = range.min.x; x < range.max.x; ++x)
                if (grid.cell({x, y, z}) != shared::CELL_EMPTY)
                    grid.writeCellUniform({x, y, z}, kEmpty);
}

EncodedRegion encodeRegion(const RegionSnapshot& region, int zstdLevel) {
    std::vector<std::uint8_t> raw;
    raw.reserve(kHeaderWords * 4 + region.cells.size() * 4 +
                region.bricks.size() * sizeof(BrickVoxels));
    const std::uint32_t header[kHeaderWords] = {kMagic,
                                                kVersion,
                                                std::uint32_t(region.size.x),
                                                std::uint32_t(region.size.y),
                                                std::uint32_t(region.size.z),
                                                std::uint32_t(region.bricks.size())};
    put(raw, header, sizeof(header));
    put(raw, region.cells.data(), region.cells.size() * sizeof(std::uint32_t));
    for (const BrickVoxels& b : region.bricks) put(raw, b.data(), sizeof(BrickVoxels));

    EncodedRegion e;
    e.key = region.key;
    e.rawBytes = raw.size();
    e.blob.resize(ZSTD_compressBound(raw.size()));
    // With the frame's checksum, a damaged row is refused rather than read as other voxels.
    ZSTD_CCtx* cctx = ZSTD_createCCtx();
    CHECK(cctx != nullptr);
    ZSTD_CCtx_setParameter(cctx, ZSTD_c_compressionLevel, zstdLevel);
    ZSTD_CCtx_setParameter(cctx, ZSTD_c_checksumFlag, 1);
    const std::size_t n =
        ZSTD_compress2(cctx, e.blob.data(), e.blob.size(), raw.data(), raw.size());
    ZSTD_freeCCtx(cctx);
    CHECK_MSG(!ZSTD_isError(n), ZSTD_getErrorName(n));  // only a bug: the bound was allocated
    e.blob.resize(n);
    return e;
}

Result<RegionSnapshot> decodeRegion(RegionKey key, std::span<const std::uint8_t> blob,
                                    glm::ivec3 expectedSize, std::size_t paletteSize,
                                    const std::string& where) {
    // The largest payload a region of this size can have: every cell a brick.
    const std::uint64_t cells =
        std::uint64_t(expectedSize.x) * std::uint64_t(expectedSize.y) * expectedSize.z;
    const std::uint64_t headerBytes = kHeaderWords * 4;
    const std::uint64_t maxBytes = headerBytes + cells * (4 + sizeof(BrickVoxels));
    const unsigned long long declared = ZSTD_getFrameContentSize(blob.data(), blob.size());
    if (declared == ZSTD_CONTENTSIZE_ERROR || declared == ZSTD_CONTENTSIZE_UNKNOWN)
        return makeError("{}: not a zstd frame with a known size ({} bytes)", where, blob.size());
    if (declared < headerBytes || declared > maxBytes)
        return makeError("{}: payload of {} bytes, outside 24..{} for a region of {}x{}x{} cells",
                         where, declared, maxBytes, expectedSize.x, expectedSize.y, expectedSize.z);
    std::vector<std::uint8_t> raw(declared);
    const std::size_t n = ZSTD_decompress(raw.data(), raw.size(), blob.data(), blob.size());
    if (ZSTD_isError(n))
        return makeError("{}: damaged compressed data: {}", where, ZSTD_getErrorName(n));
    if (n != declared)
        return makeError("{}: {} bytes after decompression, the frame says {}", where, n, declared);

    std::uint32_t header[kHeaderWords];
    std::memcpy(header, raw.data(), sizeof(header));
    if (header[0] != kMagic) return makeError("{}: not a region payload (bad magic)", where);
    if (header[1] != kVersion)
        return makeError("{}: region format version {}, this build reads {}", where, header[1],
                         kVersion);
    const glm::ivec3 size{int(header[2]), int(header[3]), int(header[4])};
    if (glm::uvec3(header[2], header[3], header[4]) != glm::uvec3(expectedSize))
        return makeError("{}: region of {}x{}x{} cells, the store's world needs {}x{}x{}", where,
                         header[2], header[3], header[4], expectedSize.x, expectedSize.y,
                         expectedSize.z);
    const std::uint64_t bricks = header[5];
    if (bricks > cells || n != headerBytes + cells * 4 + bricks * sizeof(BrickVoxels))
        return makeError("{}: {} bricks do not match a payload of {} bytes", where, bricks, n);

    RegionSnapshot s;
    s.key = key;
    s.size = size;
    s.cells.resize(cells);
    std::memcpy(s.cells.data(), raw.data() + headerBytes, cells * 4);
    s.bricks.resize(bricks);
    std::memcpy(s.bricks.data(), raw.data() + headerBytes + cells * 4,
                bricks * sizeof(BrickVoxels));
    // Bricks are numbered in cell order, each used once; materials within the palette.
    std::uint32_t nextBrick = 1;
    for (std::size_t i = 0; i < s.cells.size(); ++i) {
        const std::uint32_t v = s.cells[i];
        if (BrickGrid::cellIsBrick(v)) {
            if (v != nextBrick)
                return makeError("{}: cell {} names brick {}, expected {}", where, i, v, nextBrick);
            ++nextBrick;
        } else if (v != shared::CELL_EMPTY &&
                   ((v & ~(shared::CELL_HOMOGENEOUS | shared::CELL_MATERIAL_MASK)) != 0 ||
                    BrickGrid::cellMaterial(v) >= paletteSize ||
                    BrickGrid::cellMaterial(v) == kEmpty)) {
            return makeError("{}: cell {} has material {}, the palette has {}", where, i,
                             BrickGrid::cellMaterial(v), paletteSize);
        }
    }
    if (nextBrick - 1 != bricks)
        return makeError("{}: {} bricks stored, {} used", where, bricks, nextBrick - 1);
    for (std::size_t b = 0; b < s.bricks.size(); ++b)
        for (MaterialId m : s.bricks[b])
            if (m >= paletteSize)
                return makeError("{}: brick {} has material {}, the palette has {}", where, b, m,
                                 paletteSize);
    return s;
}

}  // namespace engine::world
