// What the benches share before their first frame: the --size as frame settings, the GPU context
// (tool_gpu.h), every world loaded up front, and output files whose folder is made first.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "render/renderer.h"
#include "tool_gpu.h"
#include "world/scene.h"

namespace vox {

// The frame settings of a --size (WIDTHxHEIGHT); an error names the option.
engine::Result<engine::render::FrameSettings> frameOfSize(const std::string& size,
                                                          const char* option = "--size");

// --size and the GPU, for the benches that check nothing else between the two.
struct BenchSetup {
    std::unique_ptr<engine::gpu::Context> gpu;
    engine::render::FrameSettings frame;
};
engine::Result<BenchSetup> openBench(const std::string& size);

// Every world read before the first frame: a typo costs nothing.
engine::Result<std::vector<engine::world::Scene>> loadWorlds(const std::vector<std::string>& names);

// Opens `path` for an atomic write, its folder made first.
engine::Status openOutputFile(engine::AtomicFile& file, const std::filesystem::path& path);

}  // namespace vox
