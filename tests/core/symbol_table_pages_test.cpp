// Releasing the dynamic linker's pages: libopenvdb (linked BIND_NOW by Debian) leaves ~26 MB of
// symbol tables resident; after the release they are gone from the resident set and OpenVDB
// still works through every relocation the linker made (a release that hit a RELRO or data page
// would reset the GOT to the file's zeros and crash the round trip below).
#include "core/symbol_table_pages.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <openvdb/openvdb.h>
#include <string>

#include "io/vdb_export.h"
#include "io/vdb_import.h"
#include "io/vdb_test_util.h"
#include "scene/scene_file.h"

using namespace engine;

namespace {

// Resident KiB of every mapping of the file whose path contains `name`.
std::size_t residentKiB(const std::string& name) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    std::size_t kib = 0;
    while (std::getline(smaps, line)) {
        if (!line.empty() && std::isxdigit(static_cast<unsigned char>(line[0])) &&
            line.find('-') < 16) {
            inside = line.find(name) != std::string::npos;
        } else if (inside && line.rfind("Rss:", 0) == 0) {
            kib += std::stoul(line.substr(4));
        }
    }
    return kib;
}

}  // namespace

TEST(SymbolTablePages, ReleasesLibopenvdbSymbolTablesAndOpenVdbStillWorks) {
    openvdb::initialize();
    const std::size_t before = residentKiB("libopenvdb");
    ReleasedPages released = releaseSymbolTablePages();
    const std::size_t after = residentKiB("libopenvdb");
    std::printf(
        "libopenvdb resident %zu KiB -> %zu KiB; released %zu segment(s), %zu KiB of address "
        "space\n",
        before, after, released.segments, released.bytes / 1024);
    // Debian's libopenvdb 10: a 26 MB read-only first segment (hash, dynsym, dynstr, rela).
    EXPECT_GE(released.bytes, std::size_t(16) << 20);
    EXPECT_LT(after + 16 * 1024, before);

    // Everything the linker resolved still resolves: export, import, and OpenVDB's own reader.
    vox_test::ScratchDir dir("pages");
    auto scene = engine::scene::loadSceneFile(std::filesystem::path(VOX_SOURCE_DIR) / "worlds" /
                                              "cornell.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const auto file = dir / "cornell.vdb";
    Status s = io::exportVdb(*scene, file, {});
    ASSERT_TRUE(s.ok()) << s.error().message;
    auto back = io::importVdb(file, {});
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(back->grid == scene->grid);
    openvdb::io::File vdb(file.string());
    vdb.open();
    auto material = openvdb::gridPtrCast<openvdb::Int32Grid>(vdb.readGrid("material"));
    ASSERT_TRUE(material);
    EXPECT_EQ(material->activeVoxelCount(), scene->grid.solidVoxels());
}
