#include "command_files.h"

namespace vox {

namespace fs = std::filesystem;

namespace {

bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::equivalent(a, b, ec)) return true;  // both exist: one file by any name
    const fs::path ra = fs::weakly_canonical(fs::absolute(a, ec), ec);
    const fs::path rb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return ra == rb;
}

}  // namespace

engine::Status checkCommandFiles(const std::vector<CommandFile>& inputs,
                                 const std::vector<CommandFile>& outputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const CommandFile& out = outputs[i];
        if (out.path.empty()) continue;
        for (const CommandFile& in : inputs)
            if (!in.path.empty() && sameFile(out.path, in.path))
                return engine::makeError("{} {} is {} {}; vox never writes over its input",
                                         out.option, out.path.string(), in.option,
                                         in.path.string());
        for (std::size_t j = 0; j < i; ++j)
            if (!outputs[j].path.empty() && sameFile(out.path, outputs[j].path))
                return engine::makeError(
                    "{} {} and {} {} are the same file; give each output its own name",
                    outputs[j].option, outputs[j].path.string(), out.option, out.path.string());
    }
    return {};
}

}  // namespace vox
