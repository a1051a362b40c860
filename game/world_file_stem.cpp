#include "game/world_file_stem.h"

#include <cctype>
#include <fmt/format.h>

#include "core/hash.h"

namespace game {

namespace {

constexpr std::size_t kMaxStem = 64;
constexpr std::size_t kHashSuffix = 9;  // "-" and 8 hex digits

}  // namespace

std::string worldFileStem(std::string_view worldName) {
    std::string safe;
    for (char c : worldName) {
        const bool allowed = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ||
                             c == '.' || c == ' ';
        if (safe.empty() && (c == '.' || c == ' ')) continue;  // no "..", no hidden file
        safe += allowed ? c : '_';
    }
    if (safe == worldName && !safe.empty() && safe.size() <= kMaxStem) return safe;
    if (safe.empty()) safe = "untitled";
    safe.resize(std::min(safe.size(), kMaxStem - kHashSuffix));
    return fmt::format("{}-{:08x}", safe, std::uint32_t(engine::fnv1a64(worldName)));
}

}  // namespace game
