// The files one command reads and writes, checked before it writes anything: no output may be
// one of its inputs or another of its outputs. Names are compared as files, not as text: each
// path is resolved against its folder (`./b.png`, `out/../b.png`, a symlinked folder), and files
// that exist are compared by identity (a symlink or a hard link to the input is the input).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"

namespace vox {

struct CommandFile {
    std::string option;  // as the user wrote it: "-o", "--exr", "the input"
    std::filesystem::path path;
};

// "vox: -o b.png and --exr b.png are the same file; give each output its own name",
// "vox: -o in.vdb is the input in.vdb; vox never writes over its input". Empty paths are skipped.
engine::Status checkCommandFiles(const std::vector<CommandFile>& inputs,
                                 const std::vector<CommandFile>& outputs);

}  // namespace vox
