#include "io/brick_payload.h"

#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace engine::io {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'V', 'O', 'X', 'B', 'R', 'I', 'K', '1'};

struct Header {
    char magic[8];
    std::uint32_t version;
    std::int32_t sizeInCells[3];
    std::uint32_t cellCount;
    std::uint32_t brickCount;
};
static_assert(sizeof(Header) == 32);

// FNV-1a 64: catches truncation and flipped bytes; not a defence against tampering.
struct Fnv1a {
    std::uint64_t h = 1469598103934665603ull;
    void add(const void* data, std::size_t bytes) {
        const auto* p = static_cast<const std::uint8_t*>(data);
        for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
    }
};

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

}  // namespace

Status writeBrickPayload(const fs::path& path, const world::BrickGrid& grid) {
    File f(std::fopen(path.c_str(), "wb"));
    if (!f) return makeError("{}: cannot write brick payload", path.string());
    std::span<const std::uint32_t> cells = grid.cells();
    // Bricks are renumbered densely in cell order, so the file does not depend on the pool's
    // free list (two equal worlds give equal files).
    std::vector<std::uint32_t> outCells(cells.begin(), cells.end());
    std::vector<std::uint32_t> bricks;
    for (std::uint32_t& c : outCells) {
        if (!world::BrickGrid::cellIsBrick(c)) continue;
        bricks.push_back(world::BrickGrid::cellBrick(c));
        c = static_cast<std::uint32_t>(bricks.size());
    }
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof(kMagic));
    h.version = 1;
    glm::ivec3 size = grid.sizeInCells();
    h.sizeInCells[0] = size.x;
    h.sizeInCells[1] = size.y;
    h.sizeInCells[2] = size.z;
    h.cellCount = static_cast<std::uint32_t>(outCells.size());
    h.brickCount = static_cast<std::uint32_t>(bricks.size());
    Fnv1a sum;
    bool ok = true;
    auto put = [&](const void* data, std::size_t bytes) {
        sum.add(data, bytes);
        ok = ok && std::fwrite(data, 1, bytes, f.get()) == bytes;
    };
    put(&h, sizeof(h));
    put(outCells.data(), outCells.size() * sizeof(std::uint32_t));
    for (std::uint32_t b : bricks) put(grid.brickVoxels(b).data(), sizeof(world::BrickVoxels));
    std::uint64_t checksum = sum.h;
    ok = ok && std::fwrite(&checksum, 1, sizeof(checksum), f.get()) == sizeof(checksum);
    ok = ok && std::fflush(f.get()) == 0;
    if (!ok) return makeError("{}: write failed (disk full?)", path.string());
    return {};
}

Result<world::BrickGrid> readBrickPayload(const fs::path& path) {
    File f(std::fopen(path.c_str(), "rb"));
    if (!f) return makeError("{}: cannot open brick payload", path.string());
    Fnv1a sum;
    auto get = [&](void* data, std::size_t bytes) {
        if (std::fread(data, 1, bytes, f.get()) != bytes) return false;
        sum.add(data, bytes);
        return true;
    };
    Header h{};
    if (!get(&h, sizeof(h)) || std::memcmp(h.magic, kMagic, sizeof(kMagic)) != 0)
        return makeError("{}: not a brick payload", path.string());
    if (h.version != 1) return makeError("{}: brick payload version {} (this build reads 1)", path.string(), h.version);
    glm::ivec3 size(h.sizeInCells[0], h.sizeInCells[1], h.sizeInCells[2]);
    std::uint64_t cellCount = std::uint64_t(std::max(size.x, 0)) * std::uint64_t(std::max(size.y, 0)) * std::uint64_t(std::max(size.z, 0));
    if (glm::any(glm::lessThan(size, glm::ivec3(1))) || glm::any(glm::greaterThan(size, glm::ivec3(1 << 12))) ||
        cellCount != h.cellCount || h.brickCount > h.cellCount)
        return makeError("{}: corrupt header ({}x{}x{} cells, {} bricks)", path.string(), size.x, size.y, size.z,
                         h.brickCount);
    std::vector<std::uint32_t> cells(h.cellCount);
    if (!get(cells.data(), cells.size() * sizeof(std::uint32_t))) return makeError("{}: truncated", path.string());
    std::vector<world::BrickVoxels> bricks(h.brickCount);
    for (world::BrickVoxels& b : bricks) {
        if (!get(b.data(), sizeof(b))) return makeError("{}: truncated", path.string());
    }
    std::uint64_t expected = sum.h, stored = 0;
    if (std::fread(&stored, 1, sizeof(stored), f.get()) != sizeof(stored)) return makeError("{}: truncated", path.string());
    if (stored != expected) return makeError("{}: checksum mismatch (corrupt file)", path.string());

    world::BrickGrid grid(size * world::kBrickDim);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                glm::ivec3 c(x, y, z);
                std::uint32_t v = cells[grid.cellIndex(c)];
                if (world::BrickGrid::cellIsBrick(v)) {
                    if (v > bricks.size()) return makeError("{}: cell references brick {} of {}", path.string(), v, bricks.size());
                    grid.writeCell(c, bricks[v - 1]);
                } else if (v != shared::CELL_EMPTY) {
                    if ((v & ~(shared::CELL_HOMOGENEOUS | shared::CELL_MATERIAL_MASK)) != 0)
                        return makeError("{}: bad cell value {:#x}", path.string(), v);
                    grid.writeCellUniform(c, world::BrickGrid::cellMaterial(v));
                }
            }
    return grid;
}

}  // namespace engine::io
