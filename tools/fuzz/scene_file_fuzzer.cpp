// libFuzzer target for the scene-file and path-file parsers (tools/fuzz/run_scene_fuzz.sh builds
// and runs it). Each input is read as a path file (parsing only: camera keys and events) and as a
// scene file. A scene file runs its generators, so the world is parsed only when it is small:
// every [world] and [[object]] size at most 64 voxels per axis, and no vdb generator (it would
// read a file named by the input). That keeps a fuzzed size from allocating a huge world — the
// readers' size limits are tested elsewhere (tests/scene/number_keys_test.cpp) — while every
// key reader, range check, generator and the [indirect] and [path] tables are reached. Any
// crash, sanitizer report, leak or timeout is a finding; errors returned as values are not.
#include <cstdint>
#include <string_view>
#include <toml++/toml.h>

#include "scene/path_file.h"
#include "scene/scene_file.h"

namespace {

constexpr std::int64_t kMaxFuzzExtent = 64;

bool smallSize(const toml::node* size) {
    const toml::array* a = size ? size->as_array() : nullptr;
    if (!a) return true;  // absent or malformed: the reader refuses it before allocating
    for (const toml::node& e : *a) {
        if (auto v = e.value<double>(); v && *v > double(kMaxFuzzExtent)) return false;
    }
    return true;
}

bool usesVdb(const toml::node* generators) {
    const toml::array* a = generators ? generators->as_array() : nullptr;
    if (!a) return false;
    for (const toml::node& g : *a) {
        const toml::table* t = g.as_table();
        if (t && t->get("type") && t->get("type")->value<std::string_view>() == "vdb") return true;
    }
    return false;
}

// Whether loading the text as a scene stays small (or is refused before any generator runs).
bool cheapToLoad(std::string_view text) {
    toml::table root;
    try {
        root = toml::parse(text, std::string_view("fuzz.toml"));
    } catch (const toml::parse_error&) {
        return true;  // a syntax error: refused at once
    }
    if (const toml::table* world = root["world"].as_table();
        world && !smallSize(world->get("size")))
        return false;
    if (usesVdb(root.get("generator"))) return false;
    if (const toml::array* objects = root["object"].as_array()) {
        for (const toml::node& o : *objects) {
            const toml::table* t = o.as_table();
            if (t && (!smallSize(t->get("size")) || usesVdb(t->get("generator")))) return false;
        }
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    auto path = engine::scene::loadFlythroughText(text, "fuzz.toml");
    (void)path;
    if (cheapToLoad(text)) {
        auto scene = engine::scene::loadSceneText(text, "fuzz.toml");
        if (scene.ok()) {
            // What a save writes must load back: the writer and the reader agree on every value.
            auto again =
                engine::scene::loadSceneText(engine::scene::sceneText(*scene), "fuzz-written.toml");
            if (!again.ok()) __builtin_trap();
        }
    }
    return 0;
}
