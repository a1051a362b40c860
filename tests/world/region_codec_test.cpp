// The region codec: every kind of cell round-trips exactly; damaged and hostile payloads give one
// error line naming the row, never a crash.
#include "world/region_codec.h"

#include <cstring>
#include <gtest/gtest.h>
#include <zstd.h>

#include "world/random_worlds.h"

namespace {

using namespace engine::world;

// Encodes every region of `grid` and decodes it into a fresh grid.
BrickGrid throughCodec(const BrickGrid& grid, std::size_t paletteSize) {
    BrickGrid out(grid.sizeInVoxels());
    const glm::ivec3 n = regionCount(grid.sizeInCells());
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) {
                const RegionKey key{x, y, z};
                const EncodedRegion e = encodeRegion(snapshotRegion(grid, key));
                auto back = decodeRegion(key, e.blob, regionCells(key, grid.sizeInCells()).size(),
                                         paletteSize, "test");
                EXPECT_TRUE(back.ok()) << back.error().message;
                if (back) writeRegion(*back, out);
            }
    return out;
}

TEST(RegionCodec, RoundTripsEveryKindOfCell) {
    using testing_worlds::Kind;
    for (Kind kind : {Kind::Sparse, Kind::Dense, Kind::Homogeneous, Kind::Mixed}) {
        // Wider than one region on x and z, clipped regions at the far edges.
        const BrickGrid grid = testing_worlds::makeWorld(kind, 7, {200, 40, 150});
        const BrickGrid back = throughCodec(grid, 1 << 16);
        EXPECT_TRUE(back == grid) << testing_worlds::kindName(kind);
        EXPECT_EQ(back.liveBricks(), grid.liveBricks());
        EXPECT_EQ(back.homogeneousCells(), grid.homogeneousCells());
    }
}

// A zstd frame holding `raw`, as the codec writes it.
std::vector<std::uint8_t> frame(const std::vector<std::uint8_t>& raw) {
    std::vector<std::uint8_t> out(ZSTD_compressBound(raw.size()));
    out.resize(ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), 1));
    return out;
}

std::vector<std::uint8_t> payload(std::vector<std::uint32_t> words) {
    std::vector<std::uint8_t> raw(words.size() * 4);
    std::memcpy(raw.data(), words.data(), raw.size());
    return raw;
}

void expectOneLineError(const engine::Result<RegionSnapshot>& r, const std::string& what) {
    ASSERT_FALSE(r.ok()) << what;
    EXPECT_EQ(r.error().message.find('\n'), std::string::npos) << r.error().message;
    EXPECT_EQ(r.error().message.rfind("w.db: region", 0), 0u) << r.error().message;
}

TEST(RegionCodec, RefusesDamagedAndHostilePayloads) {
    BrickGrid grid = testing_worlds::makeWorld(testing_worlds::Kind::Mixed, 3, {64, 64, 64});
    const RegionKey key{0, 0, 0};
    const glm::ivec3 size = regionCells(key, grid.sizeInCells()).size();
    const EncodedRegion e = encodeRegion(snapshotRegion(grid, key));
    const std::string where = "w.db: region (0, 0, 0)";
    auto decode = [&](const std::vector<std::uint8_t>& blob, std::size_t palette = 1 << 16) {
        return decodeRegion(key, blob, size, palette, where);
    };
    ASSERT_TRUE(decode(e.blob).ok());

    // Truncated at every length, and each byte flipped (the frame's checksum catches the rest).
    for (std::size_t n = 0; n < e.blob.size(); n += std::max<std::size_t>(1, e.blob.size() / 97))
        expectOneLineError(decode({e.blob.begin(), e.blob.begin() + n}), "truncated");
    for (std::size_t i = 0; i < e.blob.size(); i += std::max<std::size_t>(1, e.blob.size() / 61)) {
        std::vector<std::uint8_t> bad = e.blob;
        bad[i] ^= 0x5a;
        expectOneLineError(decode(bad), "flipped byte " + std::to_string(i));
    }
    expectOneLineError(decode({'n', 'o', 't', ' ', 'z', 's', 't', 'd'}), "not zstd");
    // The world's palette shrank under it: ids beyond it are refused.
    expectOneLineError(decode(e.blob, 2), "palette");

    const std::uint32_t cells = std::uint32_t(size.x * size.y * size.z);
    const auto header = [&](std::uint32_t bricks) {
        return std::vector<std::uint32_t>{0x47525856u,           1,
                                          std::uint32_t(size.x), std::uint32_t(size.y),
                                          std::uint32_t(size.z), bricks};
    };
    // Absurd brick count, a size other than the region's, bad magic, a brick numbered twice.
    {
        auto w = header(0xFFFFFFF0u);
        w.resize(w.size() + cells, 0);
        expectOneLineError(decode(frame(payload(w))), "absurd brick count");
    }
    {
        auto w = header(0);
        w[2] = 1000000;
        w.resize(w.size() + cells, 0);
        expectOneLineError(decode(frame(payload(w))), "absurd size");
    }
    {
        auto w = header(0);
        w[0] = 0;
        w.resize(w.size() + cells, 0);
        expectOneLineError(decode(frame(payload(w))), "magic");
    }
    {
        auto w = header(2);
        w.resize(w.size() + cells, 0);
        w[6] = 1;
        w[7] = 1;  // brick 1 twice, brick 2 never
        std::vector<std::uint8_t> raw = payload(w);
        raw.resize(raw.size() + 2 * sizeof(BrickVoxels), 0);
        expectOneLineError(decode(frame(raw)), "brick numbering");
    }
    {
        // A frame that claims a gigabyte.
        std::vector<std::uint8_t> big(1 << 20, 0);
        auto blob = frame(big);
        expectOneLineError(decode(blob), "oversized payload");
    }
}

}  // namespace
