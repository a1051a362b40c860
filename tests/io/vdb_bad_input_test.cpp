// Hostile and broken input: every case returns an error that is one line naming the file, in
// bounded time and memory, and never crashes. (The fuzz target, tools/fuzz, pushes further.)
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <random>

#include "io/vdb_import.h"
#include "io/vdb_info.h"
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
void writeBytes(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

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
    EXPECT_NE(importError(dir / "missing.vdb").find("cannot open: no such file"), std::string::npos);
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
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ASSERT_FALSE(scene.ok()) << "a file cut at " << n << " of " << full.size() << " bytes imported";
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
    EXPECT_NE(importError(cut, tiny).find("more memory than the budget of 0.1 MiB"), std::string::npos);
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
    EXPECT_NE(e.find("grid 'flow' has type vec3i, which cannot be imported"), std::string::npos) << e;
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
    EXPECT_NE(importError(dir / "rotated.vdb").find("rotated or sheared transform"), std::string::npos);
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
    for (std::size_t i = at + 13 + 4; i < std::min(bytes.size(), at + 13 + 200); ++i) bytes[i] = char(0x5A ^ i);
    writeBytes(dir / "f.vdb", bytes);
    auto scene = io::importVdb(dir / "f.vdb");
    if (!scene.ok()) {
        EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, dir / "f.vdb"));
    }
}

TEST(VdbBadInput, RootChildrenSharingAnOriginAreRefused) {
    // OpenVDB 10 would overwrite the first child with the second and leak it.
    ScratchDir dir("dup");
    samples::writeFogBox(dir / "two.vdb", glm::ivec3(4090, 1, 1), glm::ivec3(4100, 7, 7));  // two root children along x
    std::string bytes = bytesOf(dir / "two.vdb");
    // The root: one buffer, background 0, no tiles, two children, the first at (0, 0, 0).
    const std::int32_t root[8] = {1, 0, 0, 2, 0, 0, 0};
    const std::size_t start = bytes.find(std::string(reinterpret_cast<const char*>(root), 7 * sizeof(std::int32_t)));
    ASSERT_NE(start, std::string::npos);
    // The second child's origin (4096, 0, 0) follows the first child's subtree; the same bytes
    // may also occur inside it, so patch each occurrence: every variant must fail cleanly, and
    // the one that hits the origin with the duplicate-origin message.
    const std::int32_t second[3] = {4096, 0, 0}, first[3] = {0, 0, 0};
    const std::string key(reinterpret_cast<const char*>(second), sizeof(second));
    bool duplicate = false;
    for (std::size_t at = bytes.find(key, start + 28); at != std::string::npos; at = bytes.find(key, at + 1)) {
        std::string patched = bytes;
        patched.replace(at, sizeof(first), reinterpret_cast<const char*>(first), sizeof(first));
        writeBytes(dir / "dup.vdb", patched);
        duplicate |= importError(dir / "dup.vdb").find("two root children share an origin") != std::string::npos;
    }
    EXPECT_TRUE(duplicate);
}
