#include "core/log.h"

#include <cstdlib>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace engine::log {

void init() {
    static bool done = false;
    if (done) return;
    done = true;
    auto logger = spdlog::stderr_color_mt("vox");
    logger->set_pattern("[%^%l%$] %v");
    spdlog::set_default_logger(logger);
    spdlog::set_level(spdlog::level::warn);
    if (const char* level = std::getenv("VOX_LOG")) {
        spdlog::set_level(spdlog::level::from_str(level));
    }
}

}  // namespace engine::log
