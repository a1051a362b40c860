// The [indirect] table: how a world wants its indirect light (the mode and the irradiance
// cache's knobs) and its lights sampled (`sampling`), kept in world::Scene::indirect as the
// knobs' text.
#pragma once

#include "lighting/knob.h"
#include "scene/toml_reader.h"
#include "scene/toml_writer.h"
#include "world/scene.h"

namespace engine::scene {

// The lighting knob an [indirect] key names ("mode" is `indirect`, "sampling" is `sampling`, the
// rest the cache's, the path term's or the cones'), or null.
const lighting::Knob* indirectKnob(std::string_view key);
// Reads the keys of an [indirect] table into scene.indirect, checked by the knobs; `table` is
// the table's node, for messages.
void readIndirect(KeyReader& keys, const toml::node& table, world::Scene& scene);
// Writes [indirect] with the keys that differ from the defaults; nothing when none does.
void writeIndirect(const world::Scene& scene, TomlWriter& out);

}  // namespace engine::scene
