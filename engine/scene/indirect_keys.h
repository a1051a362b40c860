// The [indirect] table: how a world wants its indirect light (the mode and the irradiance
// cache's knobs), kept in world::Scene::indirect as the knobs' text.
#pragma once

#include "lighting/knob.h"
#include "scene/toml_reader.h"
#include "scene/toml_writer.h"
#include "world/scene.h"

namespace engine::scene {

// The lighting knob an [indirect] key names ("mode" is `indirect`, the rest the cache's), or null.
const lighting::Knob* indirectKnob(std::string_view key);
// Reads the keys of an [indirect] table into scene.indirect, checked by the knobs; `table` is
// the table's node, for messages.
void readIndirect(KeyReader& keys, const toml::node& table, world::Scene& scene);
// Writes [indirect] with the keys that differ from the defaults; nothing when none does.
void writeIndirect(const world::Scene& scene, TomlWriter& out);

}  // namespace engine::scene
