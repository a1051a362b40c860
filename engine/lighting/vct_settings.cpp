#include "lighting/vct_settings.h"

#include <fmt/format.h>

namespace engine::lighting {

std::string VctSettings::describe() const {
    return fmt::format("vct {} level(s) refresh 1/{}{}{}", levels, refreshPeriod,
                       leakMitigation ? fmt::format(" leak mitigation (offset {:g})", startOffset) : " no leak mitigation",
                       extraBounce ? " extra bounce" : "");
}

}  // namespace engine::lighting
