// MagicaVoxel .vox export: worlds exported and imported again come back voxel for voxel and
// colour for colour when they have at most 255 colours; larger worlds split into <= 256^3
// models; more colours are quantised with the error reported; emitters keep their strength.
#include "io/vox_export.h"

#include <gtest/gtest.h>
#include <random>

#include "io/vox_import.h"
#include "io/vox_reader.h"
#include "vdb_test_util.h"

using namespace engine;
using vox_test::ScratchDir;
namespace fs = std::filesystem;

namespace {

// Voxel for voxel: the same positions, each with the same albedo and emission.
::testing::AssertionResult sameVoxels(const world::Scene& a, const world::Scene& b) {
    if (a.grid.sizeInVoxels() != b.grid.sizeInVoxels())
        return ::testing::AssertionFailure() << "sizes differ";
    const glm::ivec3 n = a.grid.sizeInVoxels();
    std::uint64_t checked = 0;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) {
                const world::MaterialId ma = a.grid.get({x, y, z}), mb = b.grid.get({x, y, z});
                if ((ma == world::kEmpty) != (mb == world::kEmpty))
                    return ::testing::AssertionFailure()
                           << "voxel " << x << "," << y << "," << z << " solid in one only";
                if (ma == world::kEmpty) continue;
                const world::Material &pa = a.palette[ma], &pb = b.palette[mb];
                if (pa.albedo != pb.albedo || pa.emittedRadiance() != pb.emittedRadiance())
                    return ::testing::AssertionFailure()
                           << "voxel " << x << "," << y << "," << z << ": " << pa.name << " became "
                           << pb.name;
                ++checked;
            }
    if (checked != a.grid.solidVoxels()) return ::testing::AssertionFailure() << "count mismatch";
    return ::testing::AssertionSuccess();
}

// Albedos that an 8-bit sRGB palette holds exactly.
glm::vec3 paletteColour(std::mt19937& rng) {
    std::uniform_int_distribution<std::uint32_t> byte(0, 255);
    return io::voxColourToLinear(byte(rng) | byte(rng) << 8 | byte(rng) << 16);
}

world::Scene randomScene(glm::ivec3 size, int materials, std::uint64_t voxels, unsigned seed) {
    std::mt19937 rng(seed);
    world::Scene s;
    s.grid = world::BrickGrid(size);
    for (int i = 0; i < materials; ++i)
        s.palette.add({"m" + std::to_string(i), paletteColour(rng), glm::vec3(0.0f), 0.0f});
    std::uniform_int_distribution<int> x(0, size.x - 1), y(0, size.y - 1), z(0, size.z - 1),
        m(1, materials);
    for (std::uint64_t i = 0; i < voxels; ++i)
        s.grid.set({x(rng), y(rng), z(rng)}, world::MaterialId(m(rng)));
    // Corners set, so the content box is the whole world and positions survive as they are.
    s.grid.set({0, 0, 0}, 1);
    s.grid.set(size - 1, 1);
    return s;
}

world::Scene roundTrip(const world::Scene& s, const fs::path& file,
                       io::VoxExportReport* report = nullptr) {
    Status written = io::exportVox(s, file, report);
    EXPECT_TRUE(written.ok()) << written.error().message;
    auto back = io::importVox(file);
    EXPECT_TRUE(back.ok()) << back.error().message;
    return back.ok() ? std::move(*back) : world::Scene{};
}

}  // namespace

TEST(VoxExport, RoundTripIsExactUpTo255Colours) {
    ScratchDir dir("exact");
    const world::Scene s = randomScene({40, 24, 32}, 255, 5000, 7);
    io::VoxExportReport report;
    const world::Scene back = roundTrip(s, dir / "w.vox", &report);
    EXPECT_TRUE(sameVoxels(s, back));
    EXPECT_FALSE(report.quantised);
    EXPECT_EQ(report.changedVoxels, 0u);
    EXPECT_EQ(report.models, 1u);
    EXPECT_EQ(report.solidVoxels, s.grid.solidVoxels());
}

TEST(VoxExport, EmittersKeepTheirStrength) {
    ScratchDir dir("emit");
    world::Scene s;
    s.grid = world::BrickGrid({8, 8, 8});
    const glm::vec3 warm = io::voxColourToLinear(0xFF2080FFu);
    auto lamp = s.palette.add({"lamp", warm, warm, 12.5f});
    auto wall = s.palette.add({"wall", io::voxColourToLinear(0xFF808080u), glm::vec3(0.0f), 0.0f});
    s.grid.set({0, 0, 0}, *lamp);
    for (int x = 1; x < 8; ++x) s.grid.set({x, 0, 0}, *wall);
    s.grid.set({7, 7, 7}, *wall);
    io::VoxExportReport report;
    const world::Scene back = roundTrip(s, dir / "lamp.vox", &report);
    EXPECT_TRUE(sameVoxels(s, back));
    EXPECT_EQ(report.emissive, 1);
    EXPECT_EQ(back.emissiveVoxels(), 1u);
}

TEST(VoxExport, WorldsOver256SplitIntoModelsAndComeBack) {
    ScratchDir dir("split");
    const world::Scene s = randomScene({300, 20, 270}, 12, 20000, 3);
    io::VoxExportReport report;
    const world::Scene back = roundTrip(s, dir / "big.vox", &report);
    EXPECT_TRUE(sameVoxels(s, back));
    // x: 300 -> 2 models; MagicaVoxel y (the engine's z, 270) -> 2; MagicaVoxel z (20) -> 1.
    EXPECT_EQ(report.models, 4u);
    auto file = io::readVoxFile(dir / "big.vox");
    ASSERT_TRUE(file.ok()) << file.error().message;
    for (const io::VoxModel& m : file->models)
        EXPECT_TRUE(glm::all(glm::lessThanEqual(m.size, glm::ivec3(256))));
}

TEST(VoxExport, MoreThan255ColoursAreQuantisedWithTheErrorReported) {
    ScratchDir dir("quantise");
    const world::Scene s = randomScene({32, 32, 32}, 600, 8000, 11);
    io::VoxExportReport report;
    const world::Scene back = roundTrip(s, dir / "many.vox", &report);
    EXPECT_TRUE(report.quantised);
    EXPECT_LE(report.colours, 255);
    EXPECT_GT(report.changedVoxels, 0u);
    EXPECT_GT(report.meanColourError, 0.0);
    EXPECT_LE(report.meanColourError, report.maxColourError);
    EXPECT_LT(report.maxColourError, 0.5);
    // Every voxel is still there.
    EXPECT_EQ(back.grid.solidVoxels(), s.grid.solidVoxels());
    EXPECT_LE(back.palette.size() - 1, 255u);
}

TEST(VoxExport, RealFilesComeBackVoxelForVoxel) {
    const fs::path dir(VOX_SHARED_VOX_DIR);
    if (!fs::is_directory(dir))
        GTEST_SKIP() << "real .vox files not found at " << dir
                     << " (../shared/data/vox beside the checkout)";
    ScratchDir scratch("real");
    for (const char* name : {"menger.vox", "teapot.vox", "ogt_test_multiple_model_scene.vox"}) {
        SCOPED_TRACE(name);
        auto original = io::importVox(dir / name);
        ASSERT_TRUE(original.ok()) << original.error().message;
        const world::Scene back = roundTrip(*original, scratch / name);
        EXPECT_TRUE(sameVoxels(*original, back));
    }
}

TEST(VoxExport, EmptyWorldWritesAValidFile) {
    ScratchDir dir("empty");
    world::Scene s;
    s.grid = world::BrickGrid({16, 16, 16});
    ASSERT_TRUE(io::exportVox(s, dir / "empty.vox").ok());
    auto back = io::importVox(dir / "empty.vox");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->grid.solidVoxels(), 0u);
}

TEST(VoxExport, WriteIntoAMissingFolderFailsCleanly) {
    ScratchDir dir("nofolder");
    world::Scene s;
    s.grid.set({0, 0, 0}, *s.palette.add({"a", glm::vec3(0.5f), glm::vec3(0.0f), 0.0f}));
    const fs::path out = dir / "missing" / "w.vox";
    Status st = io::exportVox(s, out);
    ASSERT_FALSE(st.ok());
    EXPECT_TRUE(vox_test::isOneLineNamingFile(st.error().message, out));
    EXPECT_FALSE(fs::exists(out));
}
