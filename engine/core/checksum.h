// Checksums of files and bytes, to tell a damaged or replaced output from the one that was
// written (the frames a capture job records, tools/vox/capture_job.h). FNV-1a, 64 bits: not a
// defence against tampering, but any truncation or changed byte shows.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/error.h"

namespace engine {

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ull);

// "fnv1a64:0123456789abcdef": the algorithm is named so a record says how it was made.
std::string checksumText(std::uint64_t hash);
std::string checksumOf(std::string_view bytes);
// The checksum of a whole file; an error names the file and the system's reason.
Result<std::string> fileChecksum(const std::filesystem::path& file);

}  // namespace engine
