// Every file writer goes through core/atomic_file.h: a full disk (ENOSPC injected at each write
// and at the fsync in turn) gives one line naming the file and the reason, and the previous file
// stays byte-identical. PNG, EXR, VDB and the scene file + payload pair of scene/world_pair.h.
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <map>
#include <set>

#include "core/atomic_file.h"
#include "io/image_io.h"
#include "io/vdb_export.h"
#include "io/vox_export.h"
#include "scene/generators/vdb_keys.h"
#include "scene/scene_file.h"
#include "scene/world_pair.h"
#include "vdb_test_util.h"

using namespace engine;
using vox_test::ScratchDir;
namespace fs = std::filesystem;

namespace {

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::set<std::string> namesIn(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

// Runs `write` with the 1st, 2nd, ... write/fsync failing until it succeeds; after each failure
// the folder holds exactly what it held before, byte for byte. Returns how many failed.
int failEveryOperationInTurn(const fs::path& dir, const fs::path& named,
                             const std::function<Status()>& write) {
    std::map<std::string, std::string> before;
    for (const std::string& n : namesIn(dir)) before[n] = bytesOf(dir / n);
    int failures = 0;
    for (std::uint64_t n = 0; n < 400; ++n) {
        failWritesAfter(n);
        Status s = write();
        failWritesAfter(std::nullopt);
        if (s.ok()) return failures;
        ++failures;
        EXPECT_TRUE(vox_test::isOneLineNamingFile(s.error().message, named)) << "operation " << n;
        EXPECT_NE(s.error().message.find("No space left on device"), std::string::npos)
            << s.error().message;
        std::map<std::string, std::string> after;
        for (const std::string& name : namesIn(dir)) after[name] = bytesOf(dir / name);
        EXPECT_TRUE(after == before) << "the folder changed after failing operation " << n;
        if (after != before) return failures;
    }
    ADD_FAILURE() << "still failing after 400 operations";
    return failures;
}

std::vector<std::uint32_t> gradient(std::uint32_t w, std::uint32_t h) {
    std::vector<std::uint32_t> rgba(std::size_t(w) * h);
    for (std::size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = 0xff000000u | std::uint32_t(i * 2654435761u >> 8);
    return rgba;
}

}  // namespace

TEST(AtomicWriters, PngOnAFullDiskKeepsThePreviousFile) {
    ScratchDir dir("png");
    const fs::path file = dir / "r.png";
    ASSERT_TRUE(io::writePng(file, 8, 8, gradient(8, 8)).ok());
    const int failures = failEveryOperationInTurn(
        dir.path(), file, [&] { return io::writePng(file, 64, 64, gradient(64, 64)); });
    EXPECT_GE(failures, 2);  // the write and the fsync
    auto back = io::readPng(file);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->rgba8, gradient(64, 64));
}

TEST(AtomicWriters, ExrOnAFullDiskKeepsThePreviousFile) {
    ScratchDir dir("exr");
    const fs::path file = dir / "r.exr";
    std::vector<glm::vec4> small(4 * 4, glm::vec4(0.5f)), large(96 * 96);
    for (std::size_t i = 0; i < large.size(); ++i)
        large[i] = glm::vec4(float(i), 1.0f / float(i + 1), 2.0f, 1.0f);
    ASSERT_TRUE(io::writeExr(file, 4, 4, small).ok());
    const int failures = failEveryOperationInTurn(
        dir.path(), file, [&] { return io::writeExr(file, 96, 96, large); });
    EXPECT_GE(failures, 3);  // header, lines, offset table, fsync
    auto back = io::readExr(file);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(back->pixels == large);
}

TEST(AtomicWriters, VdbOnAFullDiskKeepsThePreviousFile) {
    ScratchDir dir("vdb");
    auto scene = scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "cornell.toml");
    ASSERT_TRUE(scene.ok());
    const fs::path file = dir / "w.vdb";
    std::ofstream(file) << "previous contents";
    const int failures =
        failEveryOperationInTurn(dir.path(), file, [&] { return io::exportVdb(*scene, file); });
    EXPECT_GE(failures, 2);
    EXPECT_NE(bytesOf(file), "previous contents");
}

TEST(AtomicWriters, VoxOnAFullDiskKeepsThePreviousFile) {
    ScratchDir dir("vox");
    auto scene = scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "cornell.toml");
    ASSERT_TRUE(scene.ok());
    const fs::path file = dir / "w.vox";
    std::ofstream(file) << "previous contents";
    const int failures =
        failEveryOperationInTurn(dir.path(), file, [&] { return io::exportVox(*scene, file); });
    EXPECT_GE(failures, 2);
    EXPECT_NE(bytesOf(file), "previous contents");
}

TEST(AtomicWriters, AnOutputThatIsAFolderSaysSo) {
    ScratchDir dir("folder");
    fs::create_directory(dir / "r.png");
    Status s = io::writePng(dir / "r.png", 1, 1, gradient(1, 1));
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message,
              (dir / "r.png").string() + " is a folder; give a file name to write");
}

// The pair: neither the scene file nor the payload changes, and no new payload is left, whichever
// write fails (payload or scene file); the scene file that is a folder leaves no payload behind.
TEST(WorldPair, AFullDiskAtAnyStepLeavesThePreviousPairUnchanged) {
    ScratchDir dir("pair");
    auto cornell = scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "cornell.toml");
    auto other = scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "thin_wall.toml");
    ASSERT_TRUE(cornell.ok() && other.ok());
    const fs::path file = dir / "world.toml";
    auto text = [&](const world::Scene& s) {
        return [&s](const std::string& payload) {
            std::vector<world::GeneratorRecord> g{scene::vdbPayloadGenerator(payload, true)};
            return scene::sceneText(s, {.generators = &g});
        };
    };
    ASSERT_TRUE(scene::writeWorldPair(*cornell, file, text(*cornell)).ok());
    // The message names whichever file failed: the journal of the payloads about to be written,
    // the payload (world.2.vdb) or the scene file.
    std::map<std::string, std::string> before;
    for (const std::string& n : namesIn(dir.path())) before[n] = bytesOf(dir / n);
    int failures = 0;
    for (std::uint64_t n = 0; n < 400; ++n) {
        failWritesAfter(n);
        Status s = scene::writeWorldPair(*other, file, text(*other));
        failWritesAfter(std::nullopt);
        if (s.ok()) break;
        ++failures;
        const std::string& m = s.error().message;
        EXPECT_TRUE(vox_test::isOneLineNamingFile(m, scene::payloadJournal(file)) ||
                    vox_test::isOneLineNamingFile(m, dir / "world.2.vdb") ||
                    vox_test::isOneLineNamingFile(m, file))
            << m;
        std::map<std::string, std::string> after;
        for (const std::string& name : namesIn(dir.path())) after[name] = bytesOf(dir / name);
        ASSERT_TRUE(after == before)
            << "the folder changed after failing operation " << n << ": " << m;
        auto loaded = scene::loadSceneFile(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        EXPECT_TRUE(loaded->grid == cornell->grid);
    }
    EXPECT_GE(failures, 5);  // journal write and fsync, payload write(s), payload fsync, scene file
                             // write, its fsync
    auto loaded = scene::loadSceneFile(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->grid == other->grid);
    // Beside the new pair, only bookkeeping (scene/world_pair.h): the world's lock file, its
    // manifest, and the journal, which stays when the disk fills up right after the commit.
    std::set<std::string> visible;
    for (const std::string& n : namesIn(dir.path()))
        if (n.front() != '.') visible.insert(n);
    EXPECT_EQ(visible, (std::set<std::string>{"world.toml", "world.2.vdb"}));
    // The next write with room tidies up: the manifest lists its payload alone, no journal stays.
    ASSERT_TRUE(scene::writeWorldPair(*cornell, file, text(*cornell)).ok());
    EXPECT_EQ(namesIn(dir.path()), (std::set<std::string>{"world.toml", "world.3.vdb", ".lock",
                                                          ".world.toml.payloads"}));
    EXPECT_EQ(
        bytesOf(scene::payloadManifest(file)),
        "# Payloads vox wrote for world.toml; removed once it names them no more\nworld.3.vdb\n");
}

TEST(WorldPair, ASceneFileThatIsAFolderLeavesNoPayload) {
    ScratchDir dir("pair_folder");
    auto cornell = scene::loadSceneFile(fs::path(VOX_SOURCE_DIR) / "worlds" / "cornell.toml");
    ASSERT_TRUE(cornell.ok());
    fs::create_directory(dir / "world.toml");
    Status s = scene::writeWorldPair(*cornell, dir / "world.toml",
                                     [](const std::string&) { return std::string(); });
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message.rfind((dir / "world.toml").string() + " is a folder", 0), 0u)
        << s.error().message;
    EXPECT_EQ(namesIn(dir.path()), (std::set<std::string>{"world.toml"}));
}
