// Command-line options shared by `vox import` and `vox info FILE.vdb` (what an import would do
// depends on them), turned into io::VdbImportOptions with errors that name the option.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "core/error.h"
#include "io/vdb_import.h"

namespace vox {

struct VdbCliOptions {
    std::string grid, colourGrid, rule = "auto", up = "auto";
    std::string offset, crop, albedo;
    float fogThreshold = 0.5f;
    int maxColours = 16;
    double voxelSize = 0.0;  // 0: the file's; given, it must be positive
    double memoryBudgetMiB = double(engine::io::kDefaultVdbMemoryBudget >> 20);
};

void addVdbImportOptions(CLI::App& cmd, VdbCliOptions& o);
engine::Result<engine::io::VdbImportOptions> toImportOptions(const VdbCliOptions& o);

}  // namespace vox
