#include "lighting/irradiance_cache_settings.h"

namespace engine::lighting {

const char* indirectName(Indirect i) {
    switch (i) {
        case Indirect::None:
            return "none";
        case Indirect::Cache:
            return "cache";
        case Indirect::Path:
            return "path";
        case Indirect::Reference:
            return "reference";
        case Indirect::Vct:
            return "vct";
    }
    return "?";
}

Result<Indirect> parseIndirect(std::string_view name) {
    for (Indirect i :
         {Indirect::None, Indirect::Cache, Indirect::Path, Indirect::Reference, Indirect::Vct}) {
        if (name == indirectName(i)) return i;
    }
    return makeError("unknown indirect mode '{}' (known: none, cache, path, reference, vct)", name);
}

}  // namespace engine::lighting
