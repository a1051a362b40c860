// Broken and hostile .vox files: each gives one line naming the file (and where it can, the
// byte offset), never a crash or a huge allocation. tools/fuzz/vox_import_fuzzer.cpp goes further.
#include <gtest/gtest.h>

#include "io/vox_import.h"
#include "io/vox_reader.h"
#include "vdb_test_util.h"
#include "vox_test_file.h"

using namespace engine;
using vox_test::Bytes;
using vox_test::ScratchDir;
using vox_test::VoxBuilder;
namespace fs = std::filesystem;

namespace {

std::string importError(const fs::path& file) {
    auto scene = io::importVox(file);
    EXPECT_FALSE(scene.ok()) << file;
    if (scene.ok()) return {};
    EXPECT_TRUE(vox_test::isOneLineNamingFile(scene.error().message, file));
    return scene.error().message;
}

std::string importError(const ScratchDir& dir, const Bytes& bytes) {
    const fs::path file = dir / "bad.vox";
    VoxBuilder::writeBytes(file, bytes);
    return importError(file);
}

VoxBuilder smallScene() {
    VoxBuilder b;
    b.model(2, 2, 2, {{0, 0, 0, 1}, {1, 1, 1, 2}});
    b.transform(0, 1, -1, {});
    b.group(1, {2});
    b.transform(2, 3, 0, {{"_t", "1 2 3"}, {"_r", "17"}});
    b.shape(3, 0);
    b.layer(0, false);
    b.palette({0xFF0000FFu, 0xFF00FF00u});
    b.material(1, {{"_type", "_emit"}, {"_emit", "1"}});
    return b;
}

}  // namespace

TEST(VoxBadInput, EveryTruncationIsRefused) {
    const Bytes whole = smallScene().bytes();
    ASSERT_TRUE(io::parseVox(whole, "whole.vox").ok());
    for (std::size_t n = 0; n < whole.size(); ++n) {
        auto r = io::parseVox(std::span(whole.data(), n), "cut.vox");
        ASSERT_FALSE(r.ok()) << "cut at " << n;
        EXPECT_TRUE(vox_test::isOneLineNamingFile(r.error().message, "cut.vox"))
            << r.error().message;
    }
    ScratchDir dir("cut");
    EXPECT_NE(importError(dir, Bytes(whole.begin(), whole.begin() + 100)).find("offset"),
              std::string::npos);
}

TEST(VoxBadInput, NotAVoxFile) {
    ScratchDir dir("notvox");
    EXPECT_NE(importError(dir, Bytes{'P', 'K', 3, 4, 0, 0, 0, 0, 0, 0})
                  .find("not a MagicaVoxel .vox file"),
              std::string::npos);
    EXPECT_NE(importError(dir, Bytes{}).find("header"), std::string::npos);
    EXPECT_NE(importError(dir / "missing.vox").find("cannot open"), std::string::npos);
}

TEST(VoxBadInput, HugeSizesAndCounts) {
    ScratchDir dir("huge");
    {
        VoxBuilder b;  // a model larger than MagicaVoxel's 256
        b.model(100000, 1, 1, {});
        EXPECT_NE(importError(dir, b.bytes()).find("model size 100000"), std::string::npos);
    }
    {
        VoxBuilder b;  // a voxel count far beyond the chunk
        Bytes size, xyzi;
        vox_test::putI32(size, 4), vox_test::putI32(size, 4), vox_test::putI32(size, 4);
        b.chunk("SIZE", size);
        vox_test::putI32(xyzi, 0x3FFFFFFF);
        b.chunk("XYZI", xyzi);
        EXPECT_NE(importError(dir, b.bytes()).find("voxel count"), std::string::npos);
    }
    {
        VoxBuilder b;  // a chunk that claims 2 GiB
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        Bytes bytes = b.bytes();
        const Bytes rest{'R', 'G', 'B', 'A', 0xFF, 0xFF, 0xFF, 0x7F, 0, 0, 0, 0};
        bytes.insert(bytes.end(), rest.begin(), rest.end());
        const std::uint32_t children = std::uint32_t(bytes.size() - 20);
        std::memcpy(bytes.data() + 16, &children, 4);
        EXPECT_NE(importError(dir, bytes).find("claims"), std::string::npos);
    }
    {
        VoxBuilder b;  // a dictionary and a string that claim more than there is
        Bytes t;
        vox_test::putI32(t, 0), vox_test::putI32(t, 1), vox_test::putI32(t, 0x7FFFFFF0);
        b.chunk("nTRN", t);
        EXPECT_NE(importError(dir, b.bytes()).find("does not fit"), std::string::npos);
        VoxBuilder c;
        Bytes u;
        vox_test::putI32(u, 0), vox_test::putI32(u, 0x40000000);
        c.chunk("nTRN", u);
        EXPECT_NE(importError(dir, c.bytes()).find("does not fit"), std::string::npos);
    }
    {
        VoxBuilder b;  // a voxel outside its model
        b.model(2, 2, 2, {{0, 0, 5, 1}});
        EXPECT_NE(importError(dir, b.bytes()).find("outside its model"), std::string::npos);
    }
    {
        VoxBuilder b;  // two instances 2^20 apart: a world past the engine's limit, refused before
                       // building
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {});
        b.group(1, {2, 4});
        b.transform(2, 3, 0, {{"_t", "-1048576 0 0"}});
        b.shape(3, 0);
        b.transform(4, 5, 0, {{"_t", "1048576 0 0"}});
        b.shape(5, 0);
        EXPECT_NE(importError(dir, b.bytes()).find("limit"), std::string::npos);
    }
    {
        VoxBuilder b;  // a translation out of range
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {{"_t", "2000000000 0 0"}});
        b.shape(1, 0);
        EXPECT_NE(importError(dir, b.bytes()).find("out of range"), std::string::npos);
    }
}

TEST(VoxBadInput, BrokenSceneGraphs) {
    ScratchDir dir("graph");
    {
        VoxBuilder b;  // a cycle: group 1 -> transform 2 -> group 1
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {});
        b.group(1, {2});
        b.transform(2, 1, 0, {});
        EXPECT_NE(importError(dir, b.bytes()).find("cycle"), std::string::npos);
    }
    {
        VoxBuilder b;  // a child id that names no node
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {});
        b.group(1, {2, 99});
        b.transform(2, 3, 0, {});
        b.shape(3, 0);
        EXPECT_NE(importError(dir, b.bytes()).find("node 99 does not exist"), std::string::npos);
    }
    {
        VoxBuilder b;  // a shape naming a model the file does not have
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {});
        b.shape(1, 5);
        EXPECT_NE(importError(dir, b.bytes()).find("names model 5"), std::string::npos);
    }
    {
        VoxBuilder b;  // no root
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(7, 8, -1, {});
        b.shape(8, 0);
        EXPECT_NE(importError(dir, b.bytes()).find("root"), std::string::npos);
    }
    {
        VoxBuilder b;  // a node id used twice
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {});
        b.shape(1, 0);
        b.shape(1, 0);
        EXPECT_NE(importError(dir, b.bytes()).find("twice"), std::string::npos);
    }
    {
        VoxBuilder b;  // a rotation byte that is no rotation
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {{"_r", "3"}});
        b.shape(1, 0);
        EXPECT_NE(importError(dir, b.bytes()).find("not a rotation"), std::string::npos);
    }
    {
        // Shared nodes fanning out: 20 levels of a group listing one transform twice would reach
        // 2^20 shapes; the walk stops at its instance bound with a message instead of running on.
        VoxBuilder b;
        b.model(1, 1, 1, {{0, 0, 0, 1}});
        b.transform(0, 1, -1, {});
        for (int level = 0; level < 22; ++level) {
            const int group = 1 + 2 * level, next = group + 1;
            b.group(group, {next, next});
            b.transform(next, level == 21 ? 100 : group + 2, 0, {});
        }
        b.shape(100, 0);
        EXPECT_NE(importError(dir, b.bytes()).find("more than"), std::string::npos);
    }
}

TEST(VoxBadInput, UnknownChunksAreSkipped) {
    ScratchDir dir("unknown");
    VoxBuilder b = smallScene();
    Bytes junk(37, 0xAB);
    b.chunk("ZZZZ", junk);
    b.write(dir / "extra.vox");
    io::VoxImportReport report;
    auto scene = io::importVox(dir / "extra.vox", {}, &report);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->grid.solidVoxels(), 2u);
    ASSERT_FALSE(report.notes.empty());
    EXPECT_NE(report.notes.back().find("ZZZZ"), std::string::npos);
}

namespace {

// True when the text holds no control character (C0, DEL): nothing that acts on a terminal,
// splits a line or cuts it.
::testing::AssertionResult noControlCharacters(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c == 0x7f)
            return ::testing::AssertionFailure()
                   << "byte " << int(c) << " at " << i << " of: " << text;
    }
    return ::testing::AssertionSuccess();
}

VoxBuilder sceneWith(const std::string& translation, const vox_test::Dict& material) {
    VoxBuilder b;
    b.model(2, 2, 2, {{0, 0, 0, 1}, {1, 1, 1, 2}});
    b.transform(0, 1, -1, {});
    b.group(1, {2});
    b.transform(2, 3, 0, {{"_t", translation}});
    b.shape(3, 0);
    b.layer(0, false);
    b.palette({0xFF0000FFu, 0xFF00FF00u});
    b.material(1, material);
    return b;
}

}  // namespace

TEST(VoxBadInput, TextFromTheFileIsEscapedInMessages) {
    ScratchDir dir("hostile_text");
    static const char kHostile[] = "1 2\x1b]2;pwned\x07\x1b[31m\n3\0";
    const std::string hostile(kHostile, sizeof(kHostile) - 1);
    const std::string message =
        importError(dir, sceneWith(hostile, {{"_type", "_diffuse"}}).bytes());
    EXPECT_NE(message.find("'_t'"), std::string::npos) << message;
    EXPECT_TRUE(noControlCharacters(message));
    EXPECT_NE(message.find("\\u001B[31m\\n3\\u0000"), std::string::npos) << message;
    // A chunk id of control characters.
    VoxBuilder b = sceneWith("1 2 3", {{"_type", "_diffuse"}});
    b.children.insert(b.children.end(), {0x1b, '[', '2', 'J', 0xff, 0xff, 0xff, 0x7f, 0, 0, 0, 0});
    const std::string chunk = importError(dir, b.bytes());
    EXPECT_TRUE(noControlCharacters(chunk));
    EXPECT_NE(chunk.find("chunk '\\u001B[2J'"), std::string::npos) << chunk;
}

TEST(VoxBadInput, EmissionBeyondWhatAWorldHoldsIsRefused) {
    // _emit is a float; times 2^_flux and the import's scale it becomes the material's strength,
    // which a scene file holds up to 1e6 (world::kRadianceRange): beyond, refused here rather
    // than imported into a world whose scene file the loader refuses.
    ScratchDir dir("emission");
    for (const char* emit : {"1e30", "3e38"}) {
        const std::string message = importError(
            dir, sceneWith("1 2 3", {{"_type", "_emit"}, {"_emit", emit}, {"_flux", "8"}}).bytes());
        EXPECT_NE(message.find("emission"), std::string::npos) << message;
    }
    auto ok = io::importVox([&] {
        const fs::path file = dir / "ok.vox";
        sceneWith("1 2 3", {{"_type", "_emit"}, {"_emit", "1"}, {"_flux", "2"}}).write(file);
        return file;
    }());
    EXPECT_TRUE(ok.ok()) << ok.error().message;
}
