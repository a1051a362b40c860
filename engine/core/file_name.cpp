#include "core/file_name.h"

#include <fmt/format.h>

#include "core/hash.h"

namespace engine {

std::string fitFileName(std::string_view name, std::size_t room) {
    if (name.size() <= room) return std::string(name);
    const std::string tail = fmt::format("~{:016x}", fnv1a64(name));
    std::size_t keep = room > tail.size() ? room - tail.size() : 0;
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80)
        --keep;  // not inside a character
    return std::string(name.substr(0, keep)) + tail;
}

}  // namespace engine
