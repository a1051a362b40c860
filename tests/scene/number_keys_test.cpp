// Every numeric key of a scene file refuses NaN, infinities and huge values with one line that
// names the file and the key's line; zero and negatives are either refused the same way or taken
// as they are (written back unchanged), never read as "the default".
//
// The keys are not listed here: each scene below is written back by the scene writer (which
// writes every key of every table it knows, defaults included), and every number in that text
// is replaced in turn. A new key is covered as soon as the writer writes it, and a new generator
// type fails GeneratorTablesCoverEveryType until it has a table here.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <variant>
#include <vector>

#include "scene/generator_registry.h"
#include "scene/scene_file.h"

namespace {

using engine::scene::loadSceneText;
using engine::scene::sceneText;

// Everything but generators: materials, an object with both kinds of key, a camera, the sky,
// [indirect] (the lighting knobs' own checks), a path with every event type.
const char* kBase = R"([world]
name = "keys"
voxel_size = 1.0
size = [32, 32, 32]

[[material]]
name = "stone"
albedo = [0.5, 0.5, 0.5]

[[material]]
name = "lamp"
albedo = [1.0, 1.0, 1.0]
emission = [1.0, 0.9, 0.8]
strength = 4.0

[[object]]
name = "cube"
size = [8, 8, 8]
loop = true
[[object.generator]]
type = "box"
min = [0, 0, 0]
max = [4, 4, 4]
material = "stone"
[[object.key]]
time = 0.0
position = [4.0, 20.0, 4.0]
rotation = [10.0, 0.0, 0.0]
[[object.key]]
time = 2.0
position = [20.0, 20.0, 4.0]
axis = [0.0, 1.0, 0.0]
angle = 90.0

[[camera]]
name = "view"
position = [16.0, 24.0, -20.0]
target = [16.0, 8.0, 16.0]
fov = 55.0

[sky]
sun_direction = [0.3, 1.0, 0.2]
sun_radiance = [3.0, 2.9, 2.6]
sky_radiance = [0.3, 0.4, 0.6]

[indirect]
mode = "cache"
directions = 128
rays = 16
bounces = 1
alpha = 0.03
fade = 0.3
max_ray = 500
budget = 150000

[path]
fps = 24.0
duration = 4.0
[[path.key]]
time = 0.0
position = [16.0, 24.0, -20.0]
target = [16.0, 8.0, 16.0]
fov = 55.0
[[path.key]]
time = 3.0
position = [20.0, 24.0, -20.0]
target = [16.0, 8.0, 16.0]
[[path.event]]
time = 0.5
type = "box"
min = [1, 1, 1]
max = [3, 3, 3]
material = "stone"
[[path.event]]
time = 1.0
type = "sphere"
center = [10.0, 10.0, 10.0]
radius = 2.0
material = "stone"
[[path.event]]
time = 1.5
type = "voxel"
at = [5, 5, 5]
material = "lamp"
[[path.event]]
time = 2.0
type = "light"
material = "lamp"
on = false
min = [0, 0, 0]
max = [32, 32, 32]
[[path.event]]
time = 2.5
type = "dynamic"
object = "cube"
)";

// One small table per generator type, run in the 32^3 world above.
struct GeneratorTable {
    const char* type;
    const char* keys;
};
const GeneratorTable kGenerators[] = {
    {"terrain",
     "top = \"stone\"\nsoil = \"stone\"\nrock = \"stone\"\nbase_height = 4.0\namplitude = 3.0\n"},
    {"box", "min = [2, 2, 2]\nmax = [6, 6, 6]\nmaterial = \"stone\"\nhollow_wall = 1\n"},
    {"sphere", "center = [16.0, 16.0, 16.0]\nradius = 4.0\nmaterial = \"stone\"\n"},
    {"cornell",
     "white = \"stone\"\nred = \"stone\"\ngreen = \"stone\"\nlight = \"lamp\"\ninterior = 16\n"
     "origin = [4, 4, 4]\nwall = 2\nlight_bricks = 1\n"},
    {"buildings", "wall = \"stone\"\nroof = \"stone\"\nwindow = \"lamp\"\ncount = 2\n"},
    {"lamps", "post = \"stone\"\nlight = \"lamp\"\ncount = 3\n"},
    {"mountain",
     "top = \"stone\"\nsoil = \"stone\"\nrock = \"stone\"\npeak_height = 12.0\nradius = 10.0\n"},
    {"scattered_lights", "light = \"lamp\"\nspacing = 8\nsize = [2, 2, 2]\nmargin = 1\n"},
    {"text", "text = \"A\"\norigin = [2, 2, 2]\nmaterial = \"stone\"\n"},
    {"menger", "origin = [0, 0, 0]\nlevel = 1\nscale = 2\nmaterial = \"stone\"\n"},
    {"apartment",
     "min = [2, 0, 2]\nsize = [16, 12, 16]\nwall = \"stone\"\nslab = \"stone\"\nwindows = "
     "[\"lamp\"]\n"},
    {"bridge", "min = [2, 2, 2]\nmax = [20, 4, 8]\ndeck = \"stone\"\n"},
};
// Types this test cannot run: vdb, vox and store need a payload file (their keys:
// tests/io/vdb_bad_input_test.cpp, tests/io/vox_import_test.cpp,
// tests/world/region_store_test.cpp).
const std::set<std::string> kNotHere = {"vdb", "vox", "store"};

// A step into the TOML tree: a key of a table or an index of an array.
using Step = std::variant<std::string, std::size_t>;
using Path = std::vector<Step>;

std::string pathName(const Path& path) {
    std::string out;
    for (const Step& s : path) {
        if (auto* k = std::get_if<std::string>(&s))
            out += (out.empty() ? "" : ".") + *k;
        else
            out += "[" + std::to_string(std::get<std::size_t>(s)) + "]";
    }
    return out;
}

void collectNumbers(toml::node& node, Path& at, std::vector<Path>& out) {
    if (node.is_number()) {
        out.push_back(at);
    } else if (toml::table* t = node.as_table()) {
        for (auto&& [k, v] : *t) {
            at.emplace_back(std::string(k.str()));
            collectNumbers(v, at, out);
            at.pop_back();
        }
    } else if (toml::array* a = node.as_array()) {
        for (std::size_t i = 0; i < a->size(); ++i) {
            at.emplace_back(i);
            collectNumbers(*a->get(i), at, out);
            at.pop_back();
        }
    }
}

toml::node* find(toml::node& root, const Path& path) {
    toml::node* n = &root;
    for (const Step& s : path) {
        if (!n) return nullptr;
        if (auto* k = std::get_if<std::string>(&s))
            n = n->is_table() ? n->as_table()->get(*k) : nullptr;
        else
            n = n->is_array() ? n->as_array()->get(std::get<std::size_t>(s)) : nullptr;
    }
    return n;
}

// Replaces the number at `path` (its parent is a table or an array).
template <typename T>
void replace(toml::table& root, const Path& path, T value) {
    Path parentPath(path.begin(), path.end() - 1);
    toml::node* parent = find(root, parentPath);
    ASSERT_NE(parent, nullptr);
    if (auto* k = std::get_if<std::string>(&path.back())) {
        parent->as_table()->insert_or_assign(*k, value);
    } else {
        toml::array& a = *parent->as_array();
        std::size_t i = std::get<std::size_t>(path.back());
        a.replace(a.cbegin() + static_cast<std::ptrdiff_t>(i), value);
    }
}

struct BadValue {
    const char* name;
    std::variant<double, std::int64_t> value;
    bool mustFail;  // NaN, infinities, huge: always refused
};
const BadValue kBadValues[] = {
    {"nan", std::nan(""), true},
    {"inf", INFINITY, true},
    {"-inf", -INFINITY, true},
    {"1e300", 1e300, true},
    {"2^40", std::int64_t(1) << 40, true},
    {"0", std::int64_t(0), false},
    {"-1", std::int64_t(-1), false},
    {"-0.5", -0.5, false},
};

struct Counts {
    int keys = 0, cases = 0, refused = 0, accepted = 0;
    std::vector<std::string> failures;
};

// Loads `text` with each number in it replaced by each bad value.
void mutateEveryNumber(const std::string& text, Counts& counts) {
    toml::table original = toml::parse(text, std::string_view("keys.toml"));
    std::vector<Path> numbers;
    Path at;
    collectNumbers(original, at, numbers);
    counts.keys += int(numbers.size());
    const std::regex oneLineAtKey(R"(^keys\.toml:([0-9]+): [^\n]+$)");
    for (const Path& path : numbers) {
        for (const BadValue& bad : kBadValues) {
            ++counts.cases;
            toml::table mutated = original;
            std::visit([&](auto v) { replace(mutated, path, v); }, bad.value);
            std::ostringstream out;
            out << mutated;
            std::string mutatedText = out.str();
            // Where the mutated key is in the text actually loaded.
            toml::table reread = toml::parse(mutatedText, std::string_view("keys.toml"));
            toml::node* leaf = find(reread, path);
            Path parentPath(path.begin(), path.end() - 1);
            toml::node* parent = find(reread, parentPath);
            auto line = [](const toml::node* n) { return n ? n->source().begin.line : 0u; };
            // An array's element reports the array's line; a number's own line otherwise.
            unsigned keyLine =
                std::holds_alternative<std::size_t>(path.back()) ? line(parent) : line(leaf);

            std::string what = pathName(path) + " = " + bad.name;
            // VOX_NUMBER_KEYS_DUMP=DIR writes each case as a file, to try on another build
            // (`vox info FILE`): how the figures "before the fix" in the report were made.
            if (const char* dump = std::getenv("VOX_NUMBER_KEYS_DUMP")) {
                std::ofstream(std::string(dump) + "/" + std::to_string(counts.cases) +
                              (bad.mustFail ? "_bad" : "_edge") + ".toml")
                    << "# " << what << "\n"
                    << mutatedText;
            }
            auto scene = loadSceneText(mutatedText, "keys.toml");
            if (!scene.ok()) {
                ++counts.refused;
                const std::string& m = scene.error().message;
                std::smatch match;
                if (!std::regex_match(m, match, oneLineAtKey))
                    counts.failures.push_back(what + ": not one line naming keys.toml:LINE: " + m);
                else if (bad.mustFail && std::stoul(match[1].str()) != keyLine)
                    counts.failures.push_back(what + ": names line " + match[1].str() +
                                              ", the key is on line " + std::to_string(keyLine) +
                                              ": " + m);
                continue;
            }
            ++counts.accepted;
            if (bad.mustFail) {
                counts.failures.push_back(what + ": accepted");
                continue;
            }
            // Accepted: the value stands as given; written back, the key holds it (not a default).
            // Exceptions: the sun direction is normalised (worlds/README.md); path events are kept
            // in time order, so a new time can move the event to another index.
            if (pathName(path).rfind("sky.sun_direction", 0) == 0 ||
                pathName(path).rfind("path.event[", 0) == 0)
                continue;
            toml::table written = toml::parse(sceneText(*scene), std::string_view("written.toml"));
            if (toml::node* back = find(written, path); back && back->is_number()) {
                double given = std::visit([](auto v) { return double(v); }, bad.value);
                if (back->value<double>().value_or(NAN) != given)
                    counts.failures.push_back(what + ": accepted but written back as " +
                                              std::to_string(back->value<double>().value_or(NAN)));
            }
        }
    }
}

std::string generatorScene(const GeneratorTable& g) {
    return std::string(kBase) + "\n[[generator]]\ntype = \"" + g.type + "\"\n" + g.keys;
}

}  // namespace

TEST(NumberKeys, GeneratorTablesCoverEveryType) {
    std::string known = engine::scene::knownGeneratorTypes();
    std::set<std::string> types;
    for (std::size_t start = 0; start <= known.size();) {
        std::size_t end = known.find(", ", start);
        if (end == std::string::npos) end = known.size();
        types.insert(known.substr(start, end - start));
        start = end + 2;
    }
    for (const GeneratorTable& g : kGenerators) types.erase(g.type);
    for (const std::string& t : kNotHere) types.erase(t);
    EXPECT_TRUE(types.empty()) << "generator type(s) without a table in number_keys_test.cpp: "
                               << *types.begin();
}

// The base tables and each generator, written back with every key, then every number replaced.
TEST(NumberKeys, EveryNumericKeyRefusesNanInfinityAndHugeWithFileAndLine) {
    Counts counts;
    for (const GeneratorTable& g : kGenerators) {
        auto scene = loadSceneText(generatorScene(g), "keys.toml");
        ASSERT_TRUE(scene.ok()) << g.type << ": " << scene.error().message;
        std::string full = sceneText(*scene);
        // The base tables' numbers once (with the first generator); each generator's own after.
        if (&g == &kGenerators[0]) {
            mutateEveryNumber(full, counts);
        } else {
            toml::table t = toml::parse(full, std::string_view("keys.toml"));
            toml::table only;
            only.insert("world", *t["world"].as_table());
            only.insert("material", *t["material"].as_array());
            only.insert("generator", *t["generator"].as_array());
            std::ostringstream out;
            out << only;
            mutateEveryNumber(out.str(), counts);
        }
    }
    std::printf("number keys: %d numbers, %d cases: %d refused, %d accepted, %zu wrong\n",
                counts.keys, counts.cases, counts.refused, counts.accepted, counts.failures.size());
    for (const std::string& f : counts.failures) ADD_FAILURE() << f;
    EXPECT_GT(counts.keys, 100);
}
