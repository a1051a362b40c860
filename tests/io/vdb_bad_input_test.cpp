// Hostile and broken input: every case returns an error that is one line naming the file, in
// bounded time and memory, and never crashes. (The fuzz target, tools/fuzz, pushes further.)
#include <chrono>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <openvdb/openvdb.h>
#include <random>

#include "io/vdb_export.h"
#include "io/vdb_import.h"
#include "io/vdb_info.h"
#include "scene/generators/vdb_keys.h"
#include "scene/scene_file.h"
#include "vdb_samples.h"
#include "vdb_test_util.h"

using namespace engine;
using vox_test::ScratchDir;
namespace fs = std::filesystem;
namespace samples = vox::samples;

namespace {

std::string bytesOf(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}
void writeBytes(const fs::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
}

std::string importError(const fs::path& file, io::VdbImportOptions o = {}) {
    auto scene = io::importVdb(file, o);
    EXPECT_FALSE(scene.ok()) << file;
    if (scene.ok()) return {};
    EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, file));
    return scene.error().message;
}

// A file with two grids of different kinds and compressions inside.
fs::path richFile(const ScratchDir& dir) {
    samples::writeLevelSetWithColour(dir / "rich.vdb");
    return dir / "rich.vdb";
}

}  // namespace

TEST(VdbBadInput, MissingEmptyAndNonVdbFiles) {
    ScratchDir dir("files");
    EXPECT_NE(importError(dir / "missing.vdb").find("cannot open: no such file"),
              std::string::npos);
    writeBytes(dir / "empty.vdb", "");
    EXPECT_NE(importError(dir / "empty.vdb").find("empty file"), std::string::npos);
    writeBytes(dir / "text.vdb", "[world]\nsize = [8, 8, 8]\n");
    EXPECT_NE(importError(dir / "text.vdb").find("not a VDB file"), std::string::npos);
    EXPECT_NE(importError(dir.path()).find("not a regular file"), std::string::npos);
    auto info = io::describeVdbFile(dir / "empty.vdb");
    ASSERT_FALSE(info.ok());
    EXPECT_TRUE(vox_test::isOneLineNamingFile(info.error().message, dir / "empty.vdb"));
}

TEST(VdbBadInput, TruncatedFilesFailCleanlyAndQuickly) {
    ScratchDir dir("truncated");
    const std::string full = bytesOf(richFile(dir));
    ASSERT_GT(full.size(), 1000u);
    const fs::path cut = dir / "cut.vdb";
    int cases = 0;
    for (std::size_t n = 1; n < full.size(); n += (n < 300 ? 5 : full.size() / 60)) {
        writeBytes(cut, full.substr(0, n));
        const auto start = std::chrono::steady_clock::now();
        auto scene = io::importVdb(cut);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ASSERT_FALSE(scene.ok()) << "a file cut at " << n << " of " << full.size()
                                 << " bytes imported";
        ASSERT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, cut)) << "cut at " << n;
        ASSERT_LT(seconds, 2.0) << "cut at " << n << ": " << scene.error().message;
        auto info = io::describeVdbFile(cut);  // must not crash or hang either
        if (!info.ok()) {
            ASSERT_TRUE(vox_test::isOneLineNamingFile(info.error().message, cut));
        }
        ++cases;
    }
    EXPECT_GT(cases, 100);
    // Over the budget while reading (before any estimate can be made) is refused too.
    io::VdbImportOptions tiny;
    tiny.memoryBudgetBytes = 64 << 10;
    writeBytes(cut, full);
    EXPECT_NE(importError(cut, tiny).find("more memory than the budget of 0.1 MiB"),
              std::string::npos);
}

TEST(VdbBadInput, RandomBytesAfterAValidHeaderFailCleanly) {
    ScratchDir dir("random");
    const std::string full = bytesOf(richFile(dir));
    const fs::path file = dir / "random.vdb";
    std::mt19937 rng(12345);
    for (int i = 0; i < 200; ++i) {
        // Keep the magic number and versions (and sometimes more), then noise.
        std::size_t keep = 8 + rng() % 200;
        std::string bytes = full.substr(0, keep);
        std::size_t noise = 16 + rng() % 4000;
        for (std::size_t k = 0; k < noise; ++k) bytes += char(rng());
        writeBytes(file, bytes);
        auto scene = io::importVdb(file);
        if (!scene.ok()) {
            ASSERT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, file)) << "case " << i;
        }
    }
}

TEST(VdbBadInput, FlippedBytesNeverCrash) {
    ScratchDir dir("flipped");
    const std::string full = bytesOf(richFile(dir));
    const fs::path file = dir / "flipped.vdb";
    std::mt19937 rng(777);
    int failed = 0;
    for (int i = 0; i < 300; ++i) {
        std::string bytes = full;
        for (int k = 0; k < 1 + int(rng() % 6); ++k) bytes[rng() % bytes.size()] = char(rng());
        writeBytes(file, bytes);
        io::VdbImportOptions o;
        o.memoryBudgetBytes = 256ull << 20;
        auto scene = io::importVdb(file, o);
        if (!scene.ok()) {
            ASSERT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, file)) << "case " << i;
            ++failed;
        }
    }
    EXPECT_GT(failed, 0);
}

TEST(VdbBadInput, WrongGridTypesAndEmptyGrids) {
    ScratchDir dir("types");
    samples::writeWrongTypes(dir / "wrong.vdb");
    std::string e = importError(dir / "wrong.vdb");
    EXPECT_NE(e.find("nothing to import"), std::string::npos) << e;
    EXPECT_NE(e.find("flow (vec3i, unusable type)"), std::string::npos) << e;
    EXPECT_NE(e.find("density (float, empty)"), std::string::npos) << e;
    io::VdbImportOptions o;
    o.grid = "flow";
    e = importError(dir / "wrong.vdb", o);
    EXPECT_NE(e.find("grid 'flow' has type vec3i, which cannot be imported"), std::string::npos)
        << e;
    o.grid = "nope";
    e = importError(dir / "wrong.vdb", o);
    EXPECT_NE(e.find("no grid named 'nope' (grids: flow, density)"), std::string::npos) << e;

    samples::writeEmptyGrid(dir / "empty.vdb");
    e = importError(dir / "empty.vdb");
    EXPECT_NE(e.find("density (float, empty)"), std::string::npos) << e;
}

TEST(VdbBadInput, TransformsWeCannotHonour) {
    ScratchDir dir("xforms");
    samples::writeRotatedGrid(dir / "rotated.vdb");
    EXPECT_NE(importError(dir / "rotated.vdb").find("rotated or sheared transform"),
              std::string::npos);
    samples::writeFrustumGrid(dir / "frustum.vdb");
    EXPECT_NE(importError(dir / "frustum.vdb").find("non-linear"), std::string::npos);
}

TEST(VdbBadInput, OverBudgetAndOverLimitAreRefusedBeforeBuilding) {
    ScratchDir dir("budget");
    samples::writeLevelSetSphere(dir / "sphere.vdb", 100.0f);  // needs about 6.4 MiB
    io::VdbImportOptions o;
    o.memoryBudgetBytes = 4ull << 20;
    std::string e = importError(dir / "sphere.vdb", o);
    EXPECT_NE(e.find("would need about"), std::string::npos) << e;
    EXPECT_NE(e.find("over the memory budget of 4.0 MiB"), std::string::npos) << e;

    samples::writeGiantTile(dir / "giant.vdb");
    e = importError(dir / "giant.vdb");
    EXPECT_NE(e.find("4096x4096x4096 voxels, over the engine's limit"), std::string::npos) << e;
    // The same file fits when cropped.
    o = {};
    o.crop = world::Box{glm::ivec3(0), glm::ivec3(64)};
    auto cropped = io::importVdb(dir / "giant.vdb", o);
    ASSERT_TRUE(cropped.ok()) << cropped.error().message;
    EXPECT_EQ(cropped->grid.solidVoxels(), 64u * 64u * 64u);
}

TEST(VdbBadInput, AbsurdAllocationsAreRefusedByTheBudget) {
    // A string length patched to 4 GiB in the file metadata: OpenVDB would fill a 4 GiB string.
    ScratchDir dir("alloc");
    samples::writeZUpTower(dir / "t.vdb", "Blender");
    std::string bytes = bytesOf(dir / "t.vdb");
    const std::size_t at = bytes.find("creator");
    ASSERT_NE(at, std::string::npos);
    const std::uint32_t huge = 0xFFFFFFF0u;
    bytes.replace(at - 4, 4, reinterpret_cast<const char*>(&huge), 4);
    writeBytes(dir / "t.vdb", bytes);
    const auto start = std::chrono::steady_clock::now();
    std::string e = importError(dir / "t.vdb");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    EXPECT_NE(e.find("memory"), std::string::npos) << e;
    // Refused for its own size, not for the total: a bigger budget would not help.
    EXPECT_NE(e.find("in one block"), std::string::npos) << e;
    EXPECT_EQ(e.find("raise --memory-budget"), std::string::npos) << e;
}

// Regressions for what the fuzz target found in OpenVDB 10 (see engine/io/openvdb_decoders.cpp,
// vdb_tree_stream.h and vdb_reader.cpp): each damaged file must fail cleanly.
TEST(VdbBadInput, DamagedDelayedLoadTablesAreIgnored) {
    // OpenVDB's own writer stores "__delayedload" tables; OpenVDB 10 would decode them with blosc.
    ScratchDir dir("delayed");
    samples::writeFogBox(dir / "f.vdb", glm::ivec3(0), glm::ivec3(20));
    std::string bytes = bytesOf(dir / "f.vdb");
    const std::size_t at = bytes.find("__delayedload");
    ASSERT_NE(at, std::string::npos) << "OpenVDB 10 writes delayed-load tables";
    for (std::size_t i = at + 13 + 4; i < std::min(bytes.size(), at + 13 + 200); ++i)
        bytes[i] = char(0x5A ^ i);
    writeBytes(dir / "f.vdb", bytes);
    auto scene = io::importVdb(dir / "f.vdb");
    if (!scene.ok()) {
        EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, dir / "f.vdb"));
    }
}

TEST(VdbBadInput, RootChildrenSharingAnOriginAreRefused) {
    // OpenVDB 10 would overwrite the first child with the second and leak it.
    ScratchDir dir("dup");
    samples::writeFogBox(dir / "two.vdb", glm::ivec3(4090, 1, 1),
                         glm::ivec3(4100, 7, 7));  // two root children along x
    std::string bytes = bytesOf(dir / "two.vdb");
    // The root: one buffer, background 0, no tiles, two children, the first at (0, 0, 0).
    const std::int32_t root[8] = {1, 0, 0, 2, 0, 0, 0};
    const std::size_t start =
        bytes.find(std::string(reinterpret_cast<const char*>(root), 7 * sizeof(std::int32_t)));
    ASSERT_NE(start, std::string::npos);
    // The second child's origin (4096, 0, 0) follows the first child's subtree; the same bytes
    // may also occur inside it, so patch each occurrence: every variant must fail cleanly, and
    // the one that hits the origin with the duplicate-origin message.
    const std::int32_t second[3] = {4096, 0, 0}, first[3] = {0, 0, 0};
    const std::string key(reinterpret_cast<const char*>(second), sizeof(second));
    bool duplicate = false;
    for (std::size_t at = bytes.find(key, start + 28); at != std::string::npos;
         at = bytes.find(key, at + 1)) {
        std::string patched = bytes;
        patched.replace(at, sizeof(first), reinterpret_cast<const char*>(first), sizeof(first));
        writeBytes(dir / "dup.vdb", patched);
        duplicate |= importError(dir / "dup.vdb").find("two root children share an origin") !=
                     std::string::npos;
    }
    EXPECT_TRUE(duplicate);
}

namespace {

// A small voxengine world with a material, a light, a camera and the default sky.
world::Scene smallWorld() {
    world::Scene scene;
    scene.name = "small";
    scene.grid = world::BrickGrid({16, 16, 16});
    world::Material stone{"stone", glm::vec3(0.5f), glm::vec3(0.0f), 0.0f};
    world::Material lamp{"lamp", glm::vec3(1.0f), glm::vec3(1.0f, 0.8f, 0.5f), 3.0f};
    const world::MaterialId s = *scene.palette.add(stone), l = *scene.palette.add(lamp);
    for (int z = 0; z < 16; ++z)
        for (int x = 0; x < 16; ++x) scene.grid.set({x, 0, z}, s);
    scene.grid.set({8, 1, 8}, l);
    scene.cameras.push_back(
        {"main", glm::vec3(8.0f, 8.0f, -10.0f), glm::vec3(8.0f, 1.0f, 8.0f), 60.0f});
    return scene;
}

}  // namespace

TEST(VdbBadInput, MetadataNumbersAreCheckedAsTheSceneKeysAre) {
    // Every number the file's metadata gives the world (voxel size, materials, cameras, sky) goes
    // through the check a scene file's keys go through: NaN, infinity or a value no scene file
    // may hold is refused with one line naming the file and the key -- never an import that
    // renders black or writes a world the loader refuses.
    ScratchDir dir("metadata");
    ASSERT_TRUE(io::exportVdb(smallWorld(), dir / "good.vdb").ok());
    ASSERT_TRUE(io::importVdb(dir / "good.vdb").ok());
    openvdb::initialize();
    openvdb::io::File good((dir / "good.vdb").string());
    good.open();
    openvdb::GridPtrVecPtr grids = good.getGrids();
    openvdb::MetaMap::Ptr meta = good.getMetadata();
    good.close();

    const float inf = std::numeric_limits<float>::infinity(),
                nan = std::numeric_limits<float>::quiet_NaN();
    const float hostile[] = {nan, inf, -inf, 1e30f};
    std::vector<std::pair<std::string, openvdb::Metadata::Ptr>> cases;
    for (const char* key :
         {"vox:world.voxel_size", "vox:material.00001.strength", "vox:camera.000.fov"})
        for (float v : hostile) cases.emplace_back(key, openvdb::FloatMetadata(v).copy());
    for (const char* key :
         {"vox:material.00001.albedo", "vox:material.00002.emission", "vox:camera.000.position",
          "vox:camera.000.target", "vox:sky.sun_direction", "vox:sky.sun_radiance",
          "vox:sky.sky_radiance"})
        for (int axis = 0; axis < 3; ++axis)
            for (float v : hostile) {
                openvdb::Vec3s value(0.5f);
                value[axis] = v;
                cases.emplace_back(key, openvdb::Vec3SMetadata(value).copy());
            }
    const fs::path bad = dir / "bad.vdb";
    for (const auto& [key, value] : cases) {
        SCOPED_TRACE(key + " = " + value->str());
        openvdb::MetaMap changed = *meta;
        changed.removeMeta(key);
        changed.insertMeta(key, *value);
        openvdb::io::File out(bad.string());
        out.write(*grids, changed);
        out.close();
        auto scene = io::importVdb(bad);
        ASSERT_FALSE(scene.ok()) << "imported";
        EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, bad));
        EXPECT_NE(scene.error().message.find(key), std::string::npos) << scene.error().message;
    }
    EXPECT_EQ(cases.size(), 3u * 4u + 7u * 3u * 4u);
}

TEST(VdbBadInput, AGridsVoxelSizeIsCheckedAsTheSceneKeyIs) {
    // A foreign grid's voxel size (its transform) becomes the world's voxel_size: refused with one
    // line naming the grid when no scene file could hold it, else the world saves and loads.
    ScratchDir dir("voxel_size");
    int tried = 0;
    for (double size : {1e30, 1e7, 1e-7, 1e-30, 0.01}) {
        SCOPED_TRACE(size);
        const fs::path file = dir / "fog.vdb";
        try {
            samples::writeFogBox(file, {0, 0, 0}, {4, 4, 4}, size);
        } catch (const openvdb::Exception&) {
            continue;  // OpenVDB itself refuses to make such a transform ("Non-zero scale values
                       // required")
        }
        ++tried;
        auto scene = io::importVdb(file);
        if (!scene.ok()) {
            EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, file));
            EXPECT_NE(scene.error().message.find("'density'"), std::string::npos)
                << scene.error().message;
            EXPECT_NE(size, 0.01) << scene.error().message;
            continue;
        }
        std::vector<world::GeneratorRecord> payload{scene::vdbPayloadGenerator("fog.vdb", false)};
        std::ofstream(dir / "fog.toml") << scene::sceneText(*scene, {.generators = &payload});
        auto loaded = scene::loadSceneFile(dir / "fog.toml");
        EXPECT_TRUE(loaded.ok()) << "imported, but the world it makes does not load: "
                                 << loaded.error().message;
    }
    EXPECT_GE(tried, 3);
}

namespace {

::testing::AssertionResult noControlCharactersBut(const std::string& text, char allowed) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c < 0x20 || c == 0x7f) && text[i] != allowed)
            return ::testing::AssertionFailure()
                   << "byte " << int(c) << " at " << i << " of: " << text;
    }
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST(VdbBadInput, TextFromTheFileIsEscapedInMessagesAndInfo) {
    // Grid names, types and metadata are the file's text: escape sequences, newlines and NULs
    // in them are shown escaped, in one-line errors and in `vox info`'s report alike.
    ScratchDir dir("hostile_text");
    static const char kHostile[] = "\x1b]2;pwned\x07\x1b[31mred\nline\0nul";
    const std::string hostile(kHostile, sizeof(kHostile) - 1);
    openvdb::initialize();
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    grid->setName(hostile);
    grid->tree().setValue(openvdb::Coord(1, 2, 3), 1.0f);
    grid->insertMeta("note", openvdb::StringMetadata(hostile));
    openvdb::MetaMap meta;
    meta.insertMeta("creator", openvdb::StringMetadata(hostile));
    meta.insertMeta(hostile, openvdb::FloatMetadata(1.0f));
    const fs::path file = dir / "hostile.vdb";
    {
        openvdb::io::File out(file.string());
        out.write({grid}, meta);
    }
    io::VdbImportOptions named;
    named.grid = "nosuch";
    const std::string message = importError(file, named);
    EXPECT_TRUE(noControlCharactersBut(message, 0)) << message;
    EXPECT_NE(message.find("\\u001B[31mred\\nline\\u0000nul"), std::string::npos) << message;

    auto info = io::describeVdbFile(file);
    ASSERT_TRUE(info.ok()) << info.error().message;
    const std::string report = io::formatVdbFileInfo(*info);
    EXPECT_TRUE(noControlCharactersBut(report, '\n'));
    EXPECT_NE(report.find("\\u001B[31mred\\nline\\u0000nul"), std::string::npos) << report;
}
