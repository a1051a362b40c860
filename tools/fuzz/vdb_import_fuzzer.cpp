// libFuzzer target for the OpenVDB import path (tools/fuzz/run_vdb_fuzz.sh builds and runs it).
// Each input is written to a file and goes through everything a user's file can reach: `vox info`
// (every grid's topology and the import plan) and an import, with options picked from the input's
// hash so the resampling, axis, crop and colour paths are exercised too. Any crash, sanitizer
// report, leak, timeout or out-of-memory is a finding; errors returned as values are not.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "io/vdb_import.h"
#include "io/vdb_info.h"

namespace {
std::filesystem::path gFile;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gFile = std::filesystem::temp_directory_path() /
            ("vox_vdb_fuzz_" + std::to_string(::getpid()) + ".vdb");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (std::FILE* f = std::fopen(gFile.c_str(), "wb")) {
        std::fwrite(data, 1, size, f);
        std::fclose(f);
    } else {
        return 0;
    }
    std::uint32_t hash = 2166136261u;
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 16777619u;

    engine::io::VdbImportOptions options;
    options.memoryBudgetBytes = 64ull << 20;  // small inputs: anything bigger is refused quickly
    auto info = engine::io::describeVdbFile(gFile, options);
    (void)info;
    switch (hash % 6) {
        case 0:
            break;
        case 1:
            options.voxelSize = 0.5f;
            options.up = engine::io::UpAxis::Z;
            break;
        case 2:
            options.voxelSize = 3.0f;
            break;
        case 3:
            options.rule = engine::io::MaterialRule::Colour;
            options.maxColours = 3;
            break;
        case 4:
            options.crop = engine::world::Box{glm::ivec3(-8), glm::ivec3(9)};
            options.rule = engine::io::MaterialRule::Height;
            break;
        case 5:
            options.offset = glm::ivec3(3, -2, 5);
            options.fogThreshold = 0.01f;
            break;
    }
    auto scene = engine::io::importVdb(gFile, options);
    (void)scene;
    return 0;
}
