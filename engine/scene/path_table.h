// The [path] table inside this layer: read from a parsed TOML table (a path file's, or a scene
// file's, scene/scene_reader.cpp) and written back by the scene writer. Public loading is
// scene/path_file.h.
#pragma once

#include <string_view>

#include "scene/toml_reader.h"
#include "scene/toml_writer.h"
#include "world/flythrough.h"

namespace engine::scene {

// The [path] table itself; fails (ParseError) with "source:line: what".
world::Flythrough readPath(const toml::table& path, std::string_view source);
// Writes [path] so that readPath gives back the same keys and events (event places aside).
void writePath(const world::Flythrough& fly, TomlWriter& out);

}  // namespace engine::scene
