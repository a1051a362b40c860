// MP4 from numbered PNG frames by running ffmpeg as a subprocess, when it is on PATH. The video
// is optional: without ffmpeg a capture still writes its frames, CSV and contact sheet.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "core/error.h"

namespace vox {

// The ffmpeg executable on PATH, if there is one.
std::optional<std::filesystem::path> findFfmpeg();

// Encodes frames `pattern` (printf style, e.g. "dir/frame_%05d.png") numbered first..first+count-1
// into an H.264 MP4 at `fps`, written atomically to `out`.
engine::Status encodeMp4(const std::filesystem::path& ffmpeg, const std::string& pattern,
                         std::uint32_t first, std::uint32_t count, double fps,
                         const std::filesystem::path& out);

}  // namespace vox
