// libFuzzer target for the MagicaVoxel .vox path (tools/fuzz/run_vox_fuzz.sh builds and runs it).
// Each input goes through what a user's file can reach: the chunk parser on the bytes, `vox info`
// (the import plan), an import under a small memory budget, and an export of whatever imported
// (which must then import again). Any crash, sanitizer report, leak, timeout or out-of-memory is
// a finding; errors returned as values are not.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>

#include "io/vox_export.h"
#include "io/vox_import.h"
#include "io/vox_reader.h"

namespace {
std::filesystem::path gFile, gExport;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const auto tmp = std::filesystem::temp_directory_path();
    gFile = tmp / ("vox_vox_fuzz_" + std::to_string(::getpid()) + ".vox");
    gExport = tmp / ("vox_vox_fuzz_" + std::to_string(::getpid()) + "_out.vox");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    auto parsed = engine::io::parseVox(std::span(data, size), "input");
    if (parsed.ok()) {
        auto instances = engine::io::voxInstances(*parsed, "input");
        (void)instances;
    }
    if (std::FILE* f = std::fopen(gFile.c_str(), "wb")) {
        std::fwrite(data, 1, size, f);
        std::fclose(f);
    } else {
        return 0;
    }
    engine::io::VoxImportOptions options;
    options.memoryBudgetBytes = 64ull << 20;  // small inputs: anything bigger is refused quickly
    auto plan = engine::io::planVoxImport(gFile, options);
    (void)plan;
    auto scene = engine::io::importVox(gFile, options);
    if (!scene) return 0;
    // What imports must export and import again with the same voxels.
    if (!engine::io::exportVox(*scene, gExport).ok()) std::abort();
    auto again = engine::io::importVox(gExport, options);
    if (!again || again->grid.solidVoxels() != scene->grid.solidVoxels()) std::abort();
    return 0;
}
