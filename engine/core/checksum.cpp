// FNV-1a checksums (core/checksum.h).
#include "core/checksum.h"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <vector>

namespace engine {

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash) {
    for (unsigned char c : bytes) {
        hash ^= c;
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::string checksumText(std::uint64_t hash) { return fmt::format("fnv1a64:{:016x}", hash); }

std::string checksumOf(std::string_view bytes) { return checksumText(fnv1a64(bytes)); }

Result<std::string> fileChecksum(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return makeError("{}: cannot read: {}", file.string(), std::strerror(errno));
    std::uint64_t hash = fnv1a64({});
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        hash = fnv1a64(std::string_view(buffer.data(), std::size_t(in.gcount())), hash);
    }
    if (in.bad()) return makeError("{}: cannot read: {}", file.string(), std::strerror(errno));
    return checksumText(hash);
}

}  // namespace engine
