// Logging: thin wrapper over spdlog so the rest of the engine does not depend on its setup.
#pragma once

#include <spdlog/spdlog.h>

namespace engine::log {

// Quiet by default for tools that print their own results; VOX_LOG=debug|info|warn overrides.
void init();

using spdlog::debug;
using spdlog::error;
using spdlog::info;
using spdlog::warn;

}  // namespace engine::log
