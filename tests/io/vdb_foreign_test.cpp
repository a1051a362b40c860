// Files nobody here wrote: made with OpenVDB's own API (tools/vdb_samples), and the two real files
// in ../shared/data/vdb. Each test compares with the analytic answer.
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <map>
#include <numbers>

#include "io/vdb_import.h"
#include "io/vdb_info.h"
#include "scene/scene_file.h"
#include "vdb_samples.h"
#include "vdb_test_util.h"

using namespace engine;
using vox_test::ScratchDir;
namespace fs = std::filesystem;
namespace samples = vox::samples;

namespace {

// Solid voxels per material name.
std::map<std::string, std::uint64_t> countByMaterial(const world::Scene& s) {
    std::map<std::string, std::uint64_t> out;
    glm::ivec3 n = s.grid.sizeInVoxels();
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                if (world::MaterialId m = s.grid.get({x, y, z})) out[s.palette[m].name]++;
    return out;
}

world::Box solidBounds(const world::Scene& s) {
    world::Box b{glm::ivec3(INT32_MAX), glm::ivec3(INT32_MIN)};
    glm::ivec3 n = s.grid.sizeInVoxels();
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                if (s.grid.get({x, y, z})) {
                    b.min = glm::min(b.min, glm::ivec3(x, y, z));
                    b.max = glm::max(b.max, glm::ivec3(x, y, z) + 1);
                }
    return b;
}

}  // namespace

TEST(VdbForeign, LevelSetSphereVolumeWithinOnePercent) {
    ScratchDir dir("sphere");
    const float radius = 40.0f;
    samples::writeLevelSetSphere(dir / "sphere.vdb", radius, glm::vec3(3.0f, -7.0f, 11.0f));
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "sphere.vdb", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const double analytic = 4.0 / 3.0 * std::numbers::pi * double(radius) * radius * radius;
    const double solid = double(scene->grid.solidVoxels());
    EXPECT_NEAR(solid / analytic, 1.0, 0.01) << "solid " << solid << " analytic " << analytic;
    EXPECT_EQ(report.plan.kind, "level set");
    EXPECT_EQ(report.solidVoxels, scene->grid.solidVoxels());
    // The interior arrives as homogeneous cells, not bricks.
    EXPECT_GT(scene->grid.homogeneousCells(), 100u);
    const world::Box b = solidBounds(*scene);
    EXPECT_EQ(b.size(), glm::ivec3(79))
        << "voxel centres strictly inside radius 40: 2 * 39 + 1 per axis";
    EXPECT_LE(report.peakTrackedBytes, report.plan.estimateBytes);
}

TEST(VdbForeign, LevelSetResampledCoarserIsConservative) {
    ScratchDir dir("coarse");
    samples::writeLevelSetSphere(dir / "sphere.vdb", 20.0f);
    io::VdbImportOptions o;
    o.voxelSize = 4.0f;  // a quarter of the resolution
    auto coarse = io::importVdb(dir / "sphere.vdb", o);
    ASSERT_TRUE(coarse.ok()) << coarse.error().message;
    // Radius 5 coarse voxels: conservative keeps every coarse voxel touching the sphere, so the
    // count lies between the sphere's volume and that of a sphere one voxel larger.
    const double solid = double(coarse->grid.solidVoxels());
    EXPECT_GE(solid, 4.0 / 3.0 * std::numbers::pi * 125.0);
    EXPECT_LE(solid, 4.0 / 3.0 * std::numbers::pi * 6.0 * 6.0 * 6.0);
    EXPECT_EQ(solidBounds(*coarse).size(), glm::ivec3(10));
    EXPECT_FLOAT_EQ(coarse->voxelSize, 4.0f);

    o.voxelSize = 0.5f;  // finer: trilinear distance
    auto fine = io::importVdb(dir / "sphere.vdb", o);
    ASSERT_TRUE(fine.ok()) << fine.error().message;
    EXPECT_NEAR(
        double(fine->grid.solidVoxels()) / (4.0 / 3.0 * std::numbers::pi * 40.0 * 40.0 * 40.0), 1.0,
        0.01);
}

TEST(VdbForeign, FogBoxAtThresholdGivesExactlyItsBox) {
    ScratchDir dir("fog");
    const glm::ivec3 lo(-5, 0, 3), hi(11, 6, 20);  // 16 x 6 x 17, plus a 0.25 shell around it
    samples::writeFogBox(dir / "fog.vdb", lo, hi);
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "fog.vdb", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(report.plan.kind, "fog volume");
    EXPECT_EQ(scene->grid.solidVoxels(), 16u * 6u * 17u);
    const glm::ivec3 offset(report.plan.offset);
    ASSERT_EQ(glm::dvec3(offset), report.plan.offset)
        << "a unit-scale import moves by whole voxels";
    EXPECT_EQ(solidBounds(*scene).min, lo + offset);
    EXPECT_EQ(solidBounds(*scene).max, hi + offset);

    io::VdbImportOptions o;
    o.fogThreshold = 0.2f;  // now the shell counts too
    scene = io::importVdb(dir / "fog.vdb", o);
    ASSERT_TRUE(scene.ok());
    EXPECT_EQ(scene->grid.solidVoxels(), 18u * 8u * 19u);
}

TEST(VdbForeign, LargeFogTilesBecomeHomogeneousCells) {
    ScratchDir dir("tiles");
    samples::writeFogBox(dir / "big.vdb", glm::ivec3(0), glm::ivec3(256, 64, 256));
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "big.vdb", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->grid.solidVoxels(), 256u * 64u * 256u);
    EXPECT_EQ(scene->grid.liveBricks(), 0u) << "all cells are whole: no brick storage";
    EXPECT_GT(report.plan.uniformCells, 8000u);
}

TEST(VdbForeign, ColourGridKeepsColoursWithinStatedError) {
    ScratchDir dir("gradient");
    const int n = 16;
    samples::writeColourGradient(dir / "g.vdb", n);
    io::VdbImportOptions o;
    o.maxColours = 16;
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "g.vdb", o, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(report.colours, 16);
    EXPECT_EQ(report.colouredVoxels, std::uint64_t(n * n * n));
    // The stated bound for all 4096 colours of a 16^3 RGB cube in 16 materials (docs/VDB.md):
    // 16 cells of the unit cube are about 0.4 on a side, half a diagonal is 0.35.
    EXPECT_LE(report.maxColourError, 0.40);
    EXPECT_LE(report.meanColourError, 0.22);
    // Every voxel is within the reported error of its original colour, and the reported mean
    // is the mean of exactly those distances.
    const glm::ivec3 offset(report.plan.offset);
    double sum = 0.0;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                world::MaterialId m = scene->grid.get(glm::ivec3(x, y, z) + offset);
                ASSERT_NE(m, world::kEmpty);
                const glm::vec3 original = glm::vec3(x, y, z) / float(n - 1);
                const double e = glm::length(scene->palette[m].albedo - original);
                ASSERT_LE(e, report.maxColourError + 1e-6);
                sum += e;
            }
    EXPECT_NEAR(sum / (n * n * n), report.meanColourError, 1e-6);
}

TEST(VdbForeign, FewColoursComeBackExactly) {
    ScratchDir dir("slabs");
    samples::writeColourSlabs(dir / "s.vdb");
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "s.vdb", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(report.colours, 6);
    EXPECT_EQ(report.maxColourError, 0.0);
    const glm::ivec3 offset(report.plan.offset);
    for (int x = 0; x < 12; ++x) {
        world::MaterialId m = scene->grid.get(glm::ivec3(x, 5, 7) + offset);
        ASSERT_NE(m, world::kEmpty);
        EXPECT_EQ(scene->palette[m].albedo, samples::slabColour(x / 2)) << "x " << x;
    }
}

TEST(VdbForeign, LevelSetTakesMaterialsFromItsColourGrid) {
    ScratchDir dir("cd");
    samples::writeLevelSetWithColour(dir / "cd.vdb");
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "cd.vdb", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(report.plan.colourGrid, "Cd");
    EXPECT_EQ(report.colours, 2);
    EXPECT_EQ(report.maxColourError, 0.0);
    const glm::ivec3 centre = glm::ivec3(report.plan.offset);
    world::MaterialId left = scene->grid.get(centre + glm::ivec3(-5, 0, 0));
    world::MaterialId right = scene->grid.get(centre + glm::ivec3(5, 0, 0));
    ASSERT_NE(left, world::kEmpty);
    ASSERT_NE(right, world::kEmpty);
    EXPECT_EQ(scene->palette[left].albedo, glm::vec3(0.8f, 0.1f, 0.1f));
    EXPECT_EQ(scene->palette[right].albedo, glm::vec3(0.1f, 0.1f, 0.8f));

    io::VdbImportOptions o;
    o.rule = io::MaterialRule::Constant;
    scene = io::importVdb(dir / "cd.vdb", o);
    ASSERT_TRUE(scene.ok());
    EXPECT_EQ(scene->palette.size(), 2u) << "empty + the constant material";
}

TEST(VdbForeign, ZUpFilesLandUpright) {
    ScratchDir dir("zup");
    // A 4x4 column 32 voxels tall along z with a 12x12 cap at its top (z = 30..31).
    samples::writeZUpTower(dir / "tower.vdb", "");
    samples::writeZUpTower(dir / "blender.vdb", "Blender/Smoke");
    io::VdbImportOptions zUp;
    zUp.up = io::UpAxis::Z;
    for (auto [file, options] : {std::pair{dir / "tower.vdb", zUp},
                                 std::pair{dir / "blender.vdb", io::VdbImportOptions{}}}) {
        io::VdbImportReport report;
        auto scene = io::importVdb(file, options, &report);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        EXPECT_TRUE(report.plan.upZ) << file;
        const world::Box b = solidBounds(*scene);
        EXPECT_EQ(b.size().y, 32) << "the tower stands along +y";
        // The cap is at the top: the top layer is 12 x 12, the bottom layer 4 x 4.
        std::uint64_t top = 0, bottom = 0;
        for (int z = b.min.z; z < b.max.z; ++z)
            for (int x = b.min.x; x < b.max.x; ++x) {
                top += scene->grid.get({x, b.max.y - 1, z}) != world::kEmpty;
                bottom += scene->grid.get({x, b.min.y, z}) != world::kEmpty;
            }
        EXPECT_EQ(top, 144u) << file;
        EXPECT_EQ(bottom, 16u) << file;
    }
    // As stored (Y-up), the same file lies on its side: 32 deep along z.
    auto lying = io::importVdb(dir / "tower.vdb");
    ASSERT_TRUE(lying.ok());
    EXPECT_EQ(solidBounds(*lying).size().z, 32);
}

TEST(VdbForeign, IntegerIdsBecomeOneMaterialEach) {
    ScratchDir dir("ids");
    samples::writeIdGrid(dir / "ids.vdb");
    auto scene = io::importVdb(dir / "ids.vdb");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto counts = countByMaterial(*scene);
    EXPECT_EQ(counts["id_7"], 512u);
    EXPECT_EQ(counts["id_42"], 512u);
    EXPECT_EQ(counts["id_-3"], 1u);
    EXPECT_EQ(counts.size(), 3u);
}

TEST(VdbForeign, NonUniformVoxelsAreResampledToCubes) {
    ScratchDir dir("nonuniform");
    samples::writeNonUniformGrid(dir / "n.vdb");  // 20^3 voxels of 0.5 x 0.5 x 1.0
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "n.vdb", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(report.plan.voxelSize, 0.5);
    EXPECT_EQ(solidBounds(*scene).size(), glm::ivec3(20, 20, 40));
    EXPECT_EQ(scene->grid.solidVoxels(), 20u * 20u * 40u);
    EXPECT_FALSE(report.plan.notes.empty());
}

TEST(VdbForeign, VoxelSizeOffsetAndCropOptions) {
    ScratchDir dir("options");
    samples::writeFogBox(dir / "f.vdb", glm::ivec3(0), glm::ivec3(16));
    io::VdbImportOptions o;
    o.voxelSize = 2.0f;
    auto half = io::importVdb(dir / "f.vdb", o);
    ASSERT_TRUE(half.ok()) << half.error().message;
    EXPECT_EQ(half->grid.solidVoxels(), 8u * 8u * 8u);

    o = {};
    o.offset = glm::ivec3(5, 6, 7);
    o.crop = world::Box{glm::ivec3(0), glm::ivec3(16, 4, 16)};
    auto moved = io::importVdb(dir / "f.vdb", o);
    ASSERT_TRUE(moved.ok()) << moved.error().message;
    EXPECT_EQ(moved->grid.solidVoxels(), 16u * 4u * 16u);
    EXPECT_EQ(solidBounds(*moved).min, glm::ivec3(5, 6, 7));

    o.rule = io::MaterialRule::Height;
    o.crop.reset();
    auto banded = io::importVdb(dir / "f.vdb", o);
    ASSERT_TRUE(banded.ok()) << banded.error().message;
    auto counts = countByMaterial(*banded);
    EXPECT_EQ(counts.size(), 4u);
    EXPECT_EQ(banded->palette[banded->grid.get({5, 6, 7})].name, "height_0");
    EXPECT_EQ(banded->palette[banded->grid.get({5, 21, 7})].name, "height_3");
}

TEST(VdbForeign, SceneFileVdbGenerator) {
    ScratchDir dir("scene");
    samples::writeLevelSetSphere(dir / "ball.vdb", 6.0f);
    std::ofstream(dir / "scene.toml") << R"([world]
size = [32, 32, 32]
[[material]]
name = "stone"
albedo = [0.4, 0.4, 0.4]
[[generator]]
type = "vdb"
source = "ball.vdb"
material = "stone"
offset = [16, 16, 16]
[[camera]]
name = "c"
position = [0, 0, -40]
target = [16, 16, 16]
)";
    auto scene = engine::scene::loadSceneFile(dir / "scene.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->palette.size(), 2u) << "the scene's stone is reused, not duplicated";
    EXPECT_EQ(scene->grid.get({16, 16, 16}), *scene->palette.find("stone"));
    EXPECT_NEAR(double(scene->grid.solidVoxels()) / (4.0 / 3.0 * std::numbers::pi * 216.0), 1.0,
                0.05);

    std::ofstream(dir / "bad.toml")
        << "[world]\nsize = [8, 8, 8]\n[[generator]]\ntype = \"vdb\"\nsource = \"nope.vdb\"\n";
    auto bad = engine::scene::loadSceneFile(dir / "bad.toml");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("bad.toml:3: "), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("nope.vdb: cannot open"), std::string::npos)
        << bad.error().message;
}

TEST(VdbRealFiles, DensityAndHeatImportsAsFog) {
    const fs::path file = vox_test::sharedVdbDir() / "usd_densityAndHeat.vdb";
    if (!fs::exists(file))
        GTEST_SKIP() << "real VDB files not found at " << file.parent_path()
                     << " (../shared/data/vdb beside the checkout)";
    auto info = io::describeVdbFile(file);
    ASSERT_TRUE(info.ok()) << info.error().message;
    ASSERT_EQ(info->grids.size(), 2u);
    EXPECT_EQ(info->grids[0].name, "density");
    EXPECT_EQ(info->grids[0].type, "float");
    EXPECT_EQ(info->grids[0].activeVoxels, 6124u);
    EXPECT_EQ(info->grids[1].name, "heat");
    EXPECT_EQ(info->grids[1].activeVoxels, 5224u);
    EXPECT_EQ(info->grids[0].bounds.size(), glm::ivec3(23, 23, 42));
    ASSERT_TRUE(info->import.ok()) << info->import.error().message;
    EXPECT_EQ(info->import->kind, "fog volume");
    EXPECT_EQ(info->import->grid, "density");
    const std::string text = io::formatVdbFileInfo(*info);
    EXPECT_NE(text.find("import would"), std::string::npos) << text;

    io::VdbImportReport report;
    auto scene = io::importVdb(file, {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const std::uint64_t atHalf = scene->grid.solidVoxels();
    EXPECT_GT(atHalf, 0u);
    EXPECT_LT(atHalf, 6124u * 2);
    io::VdbImportOptions o;
    o.fogThreshold = 0.01f;
    o.grid = "heat";
    auto heat = io::importVdb(file, o);
    ASSERT_TRUE(heat.ok()) << heat.error().message;
    EXPECT_GT(heat->grid.solidVoxels(), atHalf);
}

TEST(VdbRealFiles, BlenderSmokeCacheWithEmptyGridsFailsClearly) {
    const fs::path file = vox_test::sharedVdbDir() / "usd_smoke_000001.vdb";
    if (!fs::exists(file))
        GTEST_SKIP() << "real VDB files not found at " << file.parent_path()
                     << " (../shared/data/vdb beside the checkout)";
    auto info = io::describeVdbFile(file);
    ASSERT_TRUE(info.ok()) << info.error().message;
    EXPECT_EQ(info->grids.size(), 4u);
    for (const auto& g : info->grids) EXPECT_EQ(g.activeVoxels, 0u) << g.name;
    ASSERT_FALSE(info->import.ok());
    auto scene = io::importVdb(file);
    ASSERT_FALSE(scene.ok());
    EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, file));
    EXPECT_NE(scene.error().message.find("nothing to import"), std::string::npos)
        << scene.error().message;
    io::VdbImportOptions o;
    o.grid = "density";
    scene = io::importVdb(file, o);
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.error().message.find("grid 'density' is empty"), std::string::npos)
        << scene.error().message;
}

// Grid instances (a second grid sharing the first one's tree) are valid OpenVDB; OpenVDB writes
// an instance's block offset as 0, which the reader once took for corruption.
TEST(VdbForeign, GridInstancesReadAndImport) {
    ScratchDir dir("instances");
    samples::writeGridInstances(dir / "inst.vdb");
    auto info = io::describeVdbFile(dir / "inst.vdb");
    ASSERT_TRUE(info.ok()) << info.error().message;
    ASSERT_EQ(info->grids.size(), 2u);
    for (const auto& g : info->grids) {
        EXPECT_EQ(g.problem, "") << g.name;
        EXPECT_EQ(g.activeVoxels, 900u) << g.name;
    }
    EXPECT_EQ(info->grids[1].name, "density_copy");
    io::VdbImportOptions o;
    o.grid = "density_copy";
    auto scene = io::importVdb(dir / "inst.vdb", o);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->grid.solidVoxels(), 900u) << "the instance imports its parent's tree";
    auto first = io::importVdb(dir / "inst.vdb");
    ASSERT_TRUE(first.ok()) << first.error().message;
    EXPECT_EQ(first->grid.solidVoxels(), 900u);
}

// Blender 2.8+ fluid caches (Mantaflow) have no `creator`: the axes come from Mantaflow's grid
// metadata, or failing that from the smoke cache's grid names.
TEST(VdbForeign, BlenderFluidCachesWithoutCreatorAreZUp) {
    ScratchDir dir("mantaflow");
    samples::writeMantaflowTower(dir / "meta.vdb", true);
    samples::writeMantaflowTower(dir / "names.vdb", false);
    for (const fs::path& file : {dir / "meta.vdb", dir / "names.vdb"}) {
        io::VdbImportReport report;
        auto scene = io::importVdb(file, {}, &report);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        EXPECT_TRUE(report.plan.upZ) << file;
        EXPECT_EQ(solidBounds(*scene).size().y, 32) << file << ": the tower stands along +y";
        ASSERT_FALSE(report.plan.notes.empty());
        EXPECT_NE(report.plan.notes[0].find("Blender"), std::string::npos) << report.plan.notes[0];
    }
    // A file with neither keeps its axes (the plain tower of ZUpFilesLandUpright).
    samples::writeZUpTower(dir / "plain.vdb", "");
    io::VdbImportReport report;
    ASSERT_TRUE(io::importVdb(dir / "plain.vdb", {}, &report).ok());
    EXPECT_FALSE(report.plan.upZ);
}

TEST(VdbForeign, FogThresholdAboveTheDataIsAnError) {
    ScratchDir dir("threshold");
    samples::writeFogBox(dir / "fog.vdb", glm::ivec3(0),
                         glm::ivec3(8, 4, 4));  // 1.0 inside, 0.25 shell
    io::VdbImportOptions o;
    o.fogThreshold = 1.5f;
    auto scene = io::importVdb(dir / "fog.vdb", o);
    ASSERT_FALSE(scene.ok()) << "an empty world is not an import";
    EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, dir / "fog.vdb"));
    EXPECT_NE(scene.error().message.find("fog threshold 1.5"), std::string::npos)
        << scene.error().message;
    EXPECT_NE(scene.error().message.find("largest density in it is 1 "), std::string::npos)
        << scene.error().message;
    o.fogThreshold = 1.0f;  // at the maximum: the box
    scene = io::importVdb(dir / "fog.vdb", o);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->grid.solidVoxels(), 8u * 4u * 4u);
}

TEST(VdbForeign, VoxelSizeMustBePositive) {
    ScratchDir dir("voxelsize");
    samples::writeFogBox(dir / "fog.vdb", glm::ivec3(0), glm::ivec3(4));
    for (float bad :
         {-1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        io::VdbImportOptions o;
        o.voxelSize = bad;
        auto scene = io::importVdb(dir / "fog.vdb", o);
        ASSERT_FALSE(scene.ok()) << bad;
        EXPECT_NE(scene.error().message.find("voxel size must be positive"), std::string::npos)
            << scene.error().message;
    }
    for (const char* value : {"0", "-2", "nan"}) {
        std::ofstream(dir / "scene.toml") << "[world]\nsize = [8, 8, 8]\n[[generator]]\ntype = "
                                             "\"vdb\"\nsource = \"fog.vdb\"\nvoxel_size = "
                                          << value << "\n";
        auto scene = engine::scene::loadSceneFile(dir / "scene.toml");
        ASSERT_FALSE(scene.ok()) << value;
        EXPECT_NE(scene.error().message.find("scene.toml:6: 'voxel_size'"), std::string::npos)
            << scene.error().message;  // NaN fails as "not a number" already
    }
}

TEST(VdbForeign, DuplicateGridNamesAreSelectableByIndex) {
    ScratchDir dir("duplicates");
    samples::writeDuplicateNames(dir / "dup.vdb");
    auto info = io::describeVdbFile(dir / "dup.vdb");
    ASSERT_TRUE(info.ok()) << info.error().message;
    ASSERT_EQ(info->grids.size(), 2u);
    // OpenVDB 10 numbers every grid of a repeated name: stored "density\x1e0", "density\x1e1".
    EXPECT_EQ(info->grids[0].name, "density[0]");
    EXPECT_EQ(info->grids[1].name, "density[1]");
    for (auto [name, voxels] :
         {std::pair{"density", 8u}, std::pair{"density[0]", 8u}, std::pair{"density[1]", 27u}}) {
        io::VdbImportOptions o;
        o.grid = name;
        io::VdbImportReport report;
        auto scene = io::importVdb(dir / "dup.vdb", o, &report);
        ASSERT_TRUE(scene.ok()) << name << ": " << scene.error().message;
        EXPECT_EQ(scene->grid.solidVoxels(), voxels) << name;
        EXPECT_EQ(report.plan.grid,
                  std::string(name) == "density[1]" ? "density[1]" : "density[0]");
    }
    io::VdbImportOptions o;
    o.grid = "density[2]";
    auto missing = io::importVdb(dir / "dup.vdb", o);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("grids: density[0], density[1]"), std::string::npos)
        << missing.error().message;
}

// A tile-filled source read through the slab path writes millions of uniform cells. The world's
// dirty lists (for the GPU mirror) grew with every write until one growth asked for more than the
// per-allocation ceiling (the file's size plus 16 MiB), and the import failed with advice to
// raise --memory-budget that could not help: a 2048^3 fog at --voxel-size 1.1. A mask (always the
// slab path) of 1408^3 voxels, 5.45 million uniform cells and no bricks, needs the same growth.
TEST(VdbForeign, MillionsOfTileCellsStayWithinThePlan) {
    ScratchDir dir("tilecells");
    samples::writeMaskCube(dir / "mask.vdb", 1408);
    io::VdbImportOptions o;
    o.memoryBudgetBytes = 1ull << 30;
    io::VdbImportReport report;
    auto scene = io::importVdb(dir / "mask.vdb", o, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_FALSE(report.plan.streamed);
    EXPECT_EQ(scene->grid.homogeneousCells(), 176u * 176u * 176u);
    EXPECT_EQ(scene->grid.liveBricks(), 0u);
    EXPECT_LE(report.peakTrackedBytes, report.plan.estimateBytes) << "the plan is the truth";
}
