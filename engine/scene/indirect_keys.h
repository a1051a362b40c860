// The [indirect] table: how a world wants its indirect light (the mode and the irradiance
// cache's knobs, stored in world::Scene::indirect and Scene::cache). Reading and writing go
// through these two functions only, so a change to the settings structs stays here.
#pragma once

#include "scene/toml_reader.h"
#include "scene/toml_writer.h"
#include "world/scene.h"

namespace engine::scene {

// Reads the keys of an [indirect] table into scene.indirect and scene.cache and validates them;
// `table` is the table's node, for messages.
void readIndirect(KeyReader& keys, const toml::node& table, world::Scene& scene);
// Writes [indirect] with the keys that differ from the defaults; nothing when none does.
void writeIndirect(const world::Scene& scene, TomlWriter& out);

}  // namespace engine::scene
