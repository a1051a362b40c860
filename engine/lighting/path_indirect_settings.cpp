#include "lighting/path_indirect_settings.h"

#include <fmt/format.h>

namespace engine::lighting {

std::string PathIndirectSettings::describe() const {
    return fmt::format("path {} spp {} bounce(s){}", samples, bounces, accumulate ? " accumulated" : "");
}

}  // namespace engine::lighting
