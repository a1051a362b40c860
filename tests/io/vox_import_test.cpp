// MagicaVoxel .vox import: the real files in ../shared/data/vox against an independent count,
// and small synthetic files for what those do not hold (rotations, hidden layers and nodes,
// emission, the default palette, the scene-file generator).
#include "io/vox_import.h"

#include <fstream>
#include <gtest/gtest.h>

#include "scene/scene_file.h"
#include "vdb_test_util.h"
#include "vox_test_file.h"

using namespace engine;
using vox_test::ScratchDir;
using vox_test::VoxBuilder;
namespace fs = std::filesystem;

namespace {

fs::path sharedVoxDir() { return fs::path(VOX_SHARED_VOX_DIR); }

// Voxels by engine position, as material names.
std::map<std::tuple<int, int, int>, std::string> voxelsOf(const world::Scene& s) {
    std::map<std::tuple<int, int, int>, std::string> out;
    const glm::ivec3 n = s.grid.sizeInVoxels();
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                if (world::MaterialId m = s.grid.get({x, y, z})) out[{x, y, z}] = s.palette[m].name;
    return out;
}

}  // namespace

TEST(VoxImport, EveryRealFileMatchesAnIndependentCount) {
    const fs::path dir = sharedVoxDir();
    if (!fs::is_directory(dir))
        GTEST_SKIP() << "real .vox files not found at " << dir
                     << " (../shared/data/vox beside the checkout)";
    // Also counted by a Python script using only `struct` (chunks and scene graph walked by hand).
    const std::map<std::string, std::uint64_t> known = {
        {"chr_knight.vox", 398},
        {"menger.vox", 160000},
        {"monu1.vox", 156942},
        {"ogt_test_groups.vox", 1754},
        {"ogt_test_meta_chunk.vox", 64000},
        {"ogt_test_multiple_model_scene.vox", 12926},
        {"teapot.vox", 28411}};
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".vox") continue;
        ++files;
        const std::string name = entry.path().filename().string();
        SCOPED_TRACE(name);
        io::VoxImportReport report;
        auto scene = io::importVox(entry.path(), {}, &report);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        const std::uint64_t independent = vox_test::countVisibleVoxels(entry.path());
        EXPECT_EQ(scene->grid.solidVoxels(), independent);
        EXPECT_EQ(report.solidVoxels, independent);
        if (known.count(name)) {
            EXPECT_EQ(independent, known.at(name));
        }
        EXPECT_EQ(scene->name, entry.path().stem().string());
    }
    EXPECT_GE(files, 7);
}

TEST(VoxImport, ModelsStandUpright) {
    // A column 1 x 1 x 5 along MagicaVoxel's z (up) stands along the engine's y.
    ScratchDir dir("upright");
    VoxBuilder b;
    std::vector<VoxBuilder::V> column;
    for (int z = 0; z < 5; ++z) column.push_back({0, 0, z, 1});
    b.model(1, 1, 5, column);
    b.write(dir / "column.vox");
    auto scene = io::importVox(dir / "column.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    for (int y = 0; y < 5; ++y) EXPECT_NE(scene->grid.get({0, y, 0}), world::kEmpty) << y;
    EXPECT_EQ(scene->grid.solidVoxels(), 5u);
}

TEST(VoxImport, AxesMapZUpToYUp) {
    // Three voxels marking MagicaVoxel's +x, +y and +z from a corner: (x, y, z) -> (x, z, -y).
    ScratchDir dir("axes");
    VoxBuilder b;
    b.model(3, 3, 3, {{0, 0, 0, 1}, {2, 0, 0, 2}, {0, 2, 0, 3}, {0, 0, 2, 4}});
    b.write(dir / "axes.vox");
    auto scene = io::importVox(dir / "axes.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    // Engine positions before the shift: corner (0,0,0), +x (2,0,0), +y (0,0,-2), +z (0,2,0);
    // the shift by the lowest corner (0,0,-2) adds 2 to z.
    std::map<std::tuple<int, int, int>, std::string> expected = {
        {{0, 0, 2}, "axes_1"}, {{2, 0, 2}, "axes_2"}, {{0, 0, 0}, "axes_3"}, {{0, 2, 2}, "axes_4"}};
    EXPECT_EQ(voxelsOf(*scene), expected);
}

TEST(VoxImport, RotationsOfAnAsymmetricModel) {
    // An L of three colours in a 3 x 2 x 1 model, placed twice: as is, and turned by _r.
    // Model voxel v lands on floor(R (v + 0.5 - size/2) + t); size/2 = (1.5, 1, 0.5).
    ScratchDir dir("rotation");
    VoxBuilder b;
    b.model(3, 2, 1, {{0, 0, 0, 1}, {2, 0, 0, 2}, {0, 1, 0, 3}});
    b.transform(0, 1, -1, {});
    b.group(1, {2, 4});
    b.transform(2, 3, 0, {{"_t", "0 0 0"}});
    b.shape(3, 0);
    // R rows (0 -1 0), (1 0 0), (0 0 1): 90 degrees about z. Row 0's entry in column 1 (bits 0-1 =
    // 1), row 1's in column 0 (bits 2-3 = 0), row 0 negative (bit 4): 1 | 16 = 17.
    b.transform(4, 5, 0, {{"_r", "17"}, {"_t", "10 0 0"}});
    b.shape(5, 0);
    b.write(dir / "rot.vox");
    auto scene = io::importVox(dir / "rot.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    // MagicaVoxel positions, worked by hand:
    //  unrotated, floor(v + (-1, -0.5, 0)): (0,0,0)->(-1,-1,0) c1, (2,0,0)->(1,-1,0) c2,
    //  (0,1,0)->(-1,0,0) c3 rotated, c = v + 0.5 - size/2, R c = (-c.y, c.x, c.z), + (10,0,0),
    //  floor:
    //   (0,0,0): c (-1,-0.5,0) -> (0.5,-1,0) -> (10,-1,0) c1
    //   (2,0,0): c ( 1,-0.5,0) -> (0.5, 1,0) -> (10, 1,0) c2
    //   (0,1,0): c (-1, 0.5,0) -> (-0.5,-1,0) -> (9,-1,0) c3
    // Engine (x, z, -y), shifted by the lowest corner (-1, 0, -1): (x + 1, z, -y + 1).
    std::map<std::tuple<int, int, int>, std::string> expected = {
        {{0, 0, 2}, "rot_1"},  {{2, 0, 2}, "rot_2"},  {{0, 0, 1}, "rot_3"},
        {{11, 0, 2}, "rot_1"}, {{11, 0, 0}, "rot_2"}, {{10, 0, 2}, "rot_3"}};
    EXPECT_EQ(voxelsOf(*scene), expected);
}

TEST(VoxImport, TurningAnOddModelKeepsItsMiddleVoxel) {
    // 3 x 1 x 1, colours 1 2 3 along x, turned 180 degrees about z (_r: rows 0 and 1 negative,
    // columns 0 and 1: 4 | 16 | 32 = 52) at t = (0,0,0): the middle voxel stays, the ends swap.
    ScratchDir dir("odd");
    VoxBuilder b;
    b.model(3, 1, 1, {{0, 0, 0, 1}, {1, 0, 0, 2}, {2, 0, 0, 3}});
    b.model(1, 1, 1, {{0, 0, 0, 4}});  // a marker 3 voxels above MagicaVoxel's origin
    b.transform(0, 1, -1, {});
    b.group(1, {2, 4});
    b.transform(2, 3, 0, {{"_r", "52"}});
    b.shape(3, 0);
    b.transform(4, 5, 0, {{"_t", "0 0 3"}});
    b.shape(5, 1);
    b.write(dir / "odd.vox");
    auto scene = io::importVox(dir / "odd.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    // MagicaVoxel x: colour 3 at -1, 2 at 0, 1 at +1; the marker at (0, 0, 3). Engine x + 1.
    std::map<std::tuple<int, int, int>, std::string> expected = {
        {{0, 0, 0}, "odd_3"}, {{1, 0, 0}, "odd_2"}, {{2, 0, 0}, "odd_1"}, {{1, 3, 0}, "odd_4"}};
    EXPECT_EQ(voxelsOf(*scene), expected);
}

TEST(VoxImport, OverlappingInstancesKeepTheLaterOne) {
    // Two 2 x 2 x 2 models on the same place, the second with a hole: the second's voxels win,
    // the first shows through the hole.
    ScratchDir dir("overlap");
    VoxBuilder b;
    std::vector<VoxBuilder::V> full, holed;
    for (int i = 0; i < 8; ++i) {
        full.push_back({i & 1, (i >> 1) & 1, i >> 2, 1});
        if (i != 0) holed.push_back({i & 1, (i >> 1) & 1, i >> 2, 2});
    }
    b.model(2, 2, 2, full);
    b.model(2, 2, 2, holed);
    b.transform(0, 1, -1, {});
    b.group(1, {2, 4});
    b.transform(2, 3, 0, {});
    b.shape(3, 0);
    b.transform(4, 5, 0, {});
    b.shape(5, 1);
    b.write(dir / "overlap.vox");
    auto scene = io::importVox(dir / "overlap.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto v = voxelsOf(*scene);
    ASSERT_EQ(v.size(), 8u);
    int first = 0;
    for (const auto& [p, name] : v) first += name == "overlap_1";
    EXPECT_EQ(first, 1);
}

TEST(VoxImport, RotationBytesDecodeAndComposeExactly) {
    // Every valid _r byte decodes to a rotation matrix (det +-1) and encodes back to itself.
    int valid = 0;
    for (int bits = 0; bits < 128; ++bits) {
        io::VoxRotation r;
        if (!io::decodeVoxRotation(bits, r)) continue;
        ++valid;
        EXPECT_EQ(io::encodeVoxRotation(r), bits);
        const glm::ivec3 a = r.apply({1, 0, 0}), b = r.apply({0, 1, 0}), c = r.apply({0, 0, 1});
        EXPECT_EQ(
            std::abs(glm::dot(glm::vec3(glm::cross(glm::vec3(a), glm::vec3(b))), glm::vec3(c))),
            1.0f);
    }
    EXPECT_EQ(valid, 48);  // 6 permutations x 8 sign choices
    io::VoxRotation r;
    EXPECT_FALSE(io::decodeVoxRotation(3, r));  // column 3 does not exist
    EXPECT_FALSE(io::decodeVoxRotation(0, r));  // rows 0 and 1 in the same column
}

TEST(VoxImport, NestedGroupsComposeTransforms) {
    // root T(t = 100,0,0) -> G -> T(_r 90 about z) -> G -> T(t = 5,0,0) -> S: the inner
    // translation is turned by the outer rotation: 90 degrees about z takes (5,0,0) to (0,5,0).
    ScratchDir dir("nested");
    VoxBuilder b;
    b.model(1, 1, 1, {{0, 0, 0, 1}});
    b.model(1, 1, 1, {{0, 0, 0, 2}});
    b.transform(0, 1, -1, {});
    b.group(1, {2, 7});
    b.transform(2, 3, 0, {{"_r", "17"}});
    b.group(3, {4});
    b.transform(4, 5, 0, {{"_t", "5 0 0"}});
    b.shape(5, 0);
    b.transform(7, 8, 0, {});  // a reference voxel at the origin
    b.shape(8, 1);
    b.write(dir / "nested.vox");
    auto scene = io::importVox(dir / "nested.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    // MagicaVoxel: model 1 at (0,0,0), model 0 at (0,5,0). Engine: (0,0,0) and (0,0,-5); shift +5
    // in z.
    std::map<std::tuple<int, int, int>, std::string> expected = {{{0, 0, 5}, "nested_2"},
                                                                 {{0, 0, 0}, "nested_1"}};
    EXPECT_EQ(voxelsOf(*scene), expected);
}

TEST(VoxImport, HiddenLayersAndNodesAreLeftOut) {
    ScratchDir dir("hidden");
    VoxBuilder b;
    b.model(2, 2, 2, {{0, 0, 0, 1}, {1, 1, 1, 1}});
    b.model(1, 1, 1, {{0, 0, 0, 2}});
    b.model(1, 1, 1, {{0, 0, 0, 3}});
    b.transform(0, 1, -1, {});
    b.group(1, {2, 4, 6});
    b.transform(2, 3, 0, {});
    b.shape(3, 0);
    b.transform(4, 5, 1, {{"_t", "9 0 0"}});  // on layer 1, hidden
    b.shape(5, 1);
    b.transform(6, 7, 0, {{"_t", "0 9 0"}}, {{"_hidden", "1"}});  // a hidden node
    b.shape(7, 2);
    b.layer(0, false);
    b.layer(1, true);
    b.write(dir / "hidden.vox");
    io::VoxImportReport report;
    auto scene = io::importVox(dir / "hidden.vox", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->grid.solidVoxels(), 2u);
    EXPECT_EQ(report.instances, 1u);
    EXPECT_EQ(report.hiddenLayers, 1u);
    EXPECT_EQ(vox_test::countVisibleVoxels(dir / "hidden.vox"), 2u);
    EXPECT_FALSE(
        scene->palette.find("hidden_2"));  // colours only hidden models use make no material
}

TEST(VoxImport, PaletteColoursAreSrgbAndDefaultPaletteWhenAbsent) {
    ScratchDir dir("palette");
    VoxBuilder own;
    own.model(1, 1, 2, {{0, 0, 0, 1}, {0, 0, 1, 2}});
    own.palette({0xFF0080FFu, 0xFFFFFFFFu});  // R 255, G 128, B 0; white
    own.write(dir / "own.vox");
    auto scene = io::importVox(dir / "own.vox");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const world::Material& orange = scene->palette[*scene->palette.find("own_1")];
    EXPECT_FLOAT_EQ(orange.albedo.x, 1.0f);
    EXPECT_NEAR(orange.albedo.y, 0.2158605f, 1e-6f);  // sRGB 128 in linear
    EXPECT_FLOAT_EQ(orange.albedo.z, 0.0f);

    VoxBuilder none;
    none.model(1, 1, 1, {{0, 0, 0, 118}});
    none.write(dir / "none.vox");
    auto plain = io::importVox(dir / "none.vox");
    ASSERT_TRUE(plain.ok()) << plain.error().message;
    // MagicaVoxel's default palette: index 118 is 0xff66cc66 (R 0x66, G 0xcc, B 0x66).
    const world::Material& m = plain->palette[*plain->palette.find("none_118")];
    EXPECT_EQ(io::voxColourFromLinear(m.albedo), 0xFF66CC66u);
}

TEST(VoxImport, SrgbBytesSurviveTheLinearRoundTrip) {
    for (std::uint32_t c = 0; c < 256; ++c) {
        const std::uint32_t rgb = 0xFF000000u | c | ((255 - c) << 8) | (((c * 7) & 255) << 16);
        EXPECT_EQ(io::voxColourFromLinear(io::voxColourToLinear(rgb)), rgb);
    }
}

TEST(VoxImport, EmissiveMaterialsMapEmitAndFluxToStrength) {
    ScratchDir dir("emit");
    VoxBuilder b;
    b.model(3, 1, 1, {{0, 0, 0, 1}, {1, 0, 0, 2}, {2, 0, 0, 3}});
    b.palette({0xFF00FFFFu, 0xFF0000FFu, 0xFFFF0000u});
    b.material(1, {{"_type", "_emit"}, {"_emit", "0.5"}, {"_flux", "2"}});
    b.material(2, {{"_type", "_metal"}, {"_emit", "0.9"}});  // not an emitter: _type says metal
    b.material(3, {{"_type", "_emit"}, {"_emit", "0"}});     // no emission
    b.write(dir / "emit.vox");
    io::VoxImportReport report;
    auto scene = io::importVox(dir / "emit.vox", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const world::Material& lamp = scene->palette[*scene->palette.find("emit_1")];
    EXPECT_TRUE(lamp.emissive());
    EXPECT_FLOAT_EQ(lamp.emissionStrength, io::kVoxEmissionScale * 0.5f * 4.0f);
    EXPECT_EQ(lamp.emissionColor, lamp.albedo);
    EXPECT_FALSE(scene->palette[*scene->palette.find("emit_2")].emissive());
    EXPECT_FALSE(scene->palette[*scene->palette.find("emit_3")].emissive());
    EXPECT_EQ(report.emissiveMaterials, 1u);
    EXPECT_EQ(scene->emissiveVoxels(), 1u);
    // The pair the export writes gives every strength back exactly.
    for (float s : {0.25f, 1.0f, 3.0f, 4.0f, 5.0f, 17.5f, 64.0f, 100.0f}) {
        float emit = 0, flux = 0;
        io::voxEmitFlux(s, emit, flux);
        EXPECT_EQ(io::voxEmissionStrength({"_emit", emit, flux}), s) << s;
    }
}

TEST(VoxImport, SceneFileVoxGenerator) {
    ScratchDir dir("generator");
    VoxBuilder b;
    b.model(2, 1, 1, {{0, 0, 0, 1}, {1, 0, 0, 1}});
    b.write(dir / "bar.vox");
    std::ofstream(dir / "scene.toml") << R"([world]
size = [32, 32, 32]
[[material]]
name = "stone"
albedo = [0.4, 0.4, 0.4]
[[generator]]
type = "box"
min = [0, 0, 0]
max = [32, 1, 32]
material = "stone"
[[generator]]
type = "vox"
source = "bar.vox"
offset = [10, 1, 12]
)";
    auto scene = scene::loadSceneFile(dir / "scene.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->palette[scene->grid.get({10, 1, 12})].name, "bar_1");
    EXPECT_EQ(scene->palette[scene->grid.get({11, 1, 12})].name, "bar_1");
    EXPECT_EQ(scene->grid.solidVoxels(), 32u * 32u + 2u);
    // Written back with its keys, and read again the same.
    std::string text = scene::sceneText(*scene, {});
    EXPECT_NE(text.find("type = \"vox\""), std::string::npos) << text;
    EXPECT_NE(text.find("source = \"bar.vox\""), std::string::npos) << text;
}
