#include "world/flythrough_file.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace engine::world {

namespace {

struct ParseError {
    std::string message;
};

// Reads one TOML table and insists every key in it was understood (catches typos). The same
// idea as scene_file.cpp's reader, kept separate while the scene format is being extended on
// other branches.
class Table {
public:
    Table(const std::string& source, const toml::table& t) : mSource(source), mTable(t) {}
    ~Table() noexcept(false) {
        if (std::uncaught_exceptions()) return;
        for (auto&& [key, node] : mTable) {
            if (!mUsed.count(std::string(key.str()))) fail(&node, "unknown key '{}'", key.str());
        }
    }

    template <typename... Args>
    [[noreturn]] void fail(const toml::node* at, fmt::format_string<Args...> f,
                           Args&&... args) const {
        throw ParseError{where(at) + ": " + fmt::format(f, std::forward<Args>(args)...)};
    }
    // "file:line" of `at`, or just the file when there is no node to point at.
    std::string where(const toml::node* at) const {
        if (at && at->source().begin.line)
            return fmt::format("{}:{}", mSource, at->source().begin.line);
        return mSource;
    }

    const toml::node* node(std::string_view key) {
        mUsed.insert(std::string(key));
        return mTable.get(key);
    }
    const toml::table& raw() const { return mTable; }

    double number(std::string_view key, double fallback, bool required = false) {
        const toml::node* n = node(key);
        if (!n) {
            if (required) fail(&mTable, "missing '{}'", key);
            return fallback;
        }
        if (auto v = n->value<double>(); v && std::isfinite(*v)) return *v;
        fail(n, "'{}' must be a number", key);
    }
    bool boolean(std::string_view key, bool fallback, bool required = false) {
        const toml::node* n = node(key);
        if (!n) {
            if (required) fail(&mTable, "missing '{}'", key);
            return fallback;
        }
        if (auto v = n->value<bool>()) return *v;
        fail(n, "'{}' must be true or false", key);
    }
    std::string string(std::string_view key, bool required = true) {
        const toml::node* n = node(key);
        if (!n) {
            if (required) fail(&mTable, "missing '{}'", key);
            return {};
        }
        if (auto v = n->value<std::string>()) return *v;
        fail(n, "'{}' must be a string", key);
    }
    glm::dvec3 vec3(std::string_view key, bool required = true) {
        const toml::node* n = node(key);
        if (!n) {
            if (required) fail(&mTable, "missing '{}'", key);
            return glm::dvec3(0.0);
        }
        const toml::array* a = n->as_array();
        glm::dvec3 out(0.0);
        bool ok = a && a->size() == 3;
        for (int i = 0; ok && i < 3; ++i) {
            auto v = (*a)[std::size_t(i)].value<double>();
            ok = v && std::isfinite(*v) && std::abs(*v) <= 1e7;
            if (ok) out[i] = *v;
        }
        if (!ok) fail(n, "'{}' must be an array of 3 numbers", key);
        return out;
    }
    glm::ivec3 ivec3(std::string_view key) {
        glm::dvec3 v = vec3(key);
        if (glm::any(glm::notEqual(glm::floor(v), v)) ||
            glm::any(glm::greaterThan(glm::abs(v), glm::dvec3(1 << 20))))
            fail(node(key), "'{}' must hold whole numbers of voxels", key);
        return glm::ivec3(v);
    }

private:
    const std::string& mSource;
    const toml::table& mTable;
    std::set<std::string> mUsed;
};

class PathParser {
public:
    explicit PathParser(std::string source) : mSource(std::move(source)) {}

    Flythrough parse(const toml::table& root) {
        Table top(mSource, root);
        // A scene file's other tables are the scene loader's business; a path file has only [path].
        if (root.contains("world")) {
            for (auto&& [key, node] : root) top.node(key.str());
        }
        const toml::node* n = top.node("path");
        if (!n) top.fail(nullptr, "no [path] table (camera keys and events for vox capture)");
        const toml::table* t = n->as_table();
        if (!t) top.fail(n, "'path' must be a table ([path])");
        return parsePath(*t);
    }

private:
    Flythrough parsePath(const toml::table& t) {
        Table path(mSource, t);
        Flythrough fly;
        fly.source = mSource;
        fly.fps = path.number("fps", 30.0);
        if (!(fly.fps > 0.0 && fly.fps <= 1000.0))
            path.fail(path.node("fps"), "'fps' must be in (0, 1000]");

        std::vector<CameraKey> keys;
        const toml::node* k = path.node("key");
        const toml::array* ka = k ? k->as_array() : nullptr;
        if (!ka || ka->empty())
            path.fail(k ? k : &t, "[path] needs at least one camera key ([[path.key]])");
        for (const toml::node& key : *ka) keys.push_back(parseKey(key, keys));

        double lastKey = keys.back().time;
        fly.duration = path.number("duration", lastKey);
        if (fly.duration < lastKey || fly.duration > 24.0 * 3600.0)
            path.fail(path.node("duration"),
                      "'duration' must be at least the last key's time ({} s) and at most a day",
                      lastKey);
        fly.camera = CameraPath(std::move(keys));

        std::vector<TimelineEvent> events;
        if (const toml::node* e = path.node("event")) {
            const toml::array* ea = e->as_array();
            if (!ea) path.fail(e, "'event' must be an array of tables ([[path.event]])");
            for (const toml::node& event : *ea) events.push_back(parseEvent(event, fly.duration));
        }
        fly.timeline = Timeline(std::move(events));
        return fly;
    }

    CameraKey parseKey(const toml::node& node, const std::vector<CameraKey>& previous) {
        const toml::table* t = node.as_table();
        if (!t) throw ParseError{mSource + ": each [[path.key]] must be a table"};
        Table k(mSource, *t);
        CameraKey key;
        key.time = k.number("time", 0.0, true);
        key.position = glm::vec3(k.vec3("position"));
        key.target = glm::vec3(k.vec3("target"));
        key.fovYDegrees = static_cast<float>(
            k.number("fov", previous.empty() ? 60.0 : previous.back().fovYDegrees));
        if (key.time < 0.0) k.fail(k.node("time"), "'time' must not be negative");
        if (!previous.empty() && key.time <= previous.back().time)
            k.fail(k.node("time"), "key times must increase: {} s after {} s", key.time,
                   previous.back().time);
        if (key.fovYDegrees <= 1.0f || key.fovYDegrees >= 179.0f)
            k.fail(k.node("fov"), "'fov' must be in (1, 179) degrees");
        if (glm::length(key.target - key.position) < 1e-3f)
            k.fail(&node, "key target equals its position");
        return key;
    }

    TimelineEvent parseEvent(const toml::node& node, double duration) {
        const toml::table* t = node.as_table();
        if (!t) throw ParseError{mSource + ": each [[path.event]] must be a table"};
        Table e(mSource, *t);
        TimelineEvent ev;
        ev.where = e.where(&node);
        ev.time = e.number("time", 0.0, true);
        if (ev.time < 0.0 || ev.time > duration)
            e.fail(e.node("time"), "event time {} s is outside the path's 0..{} s", ev.time,
                   duration);
        std::string type = e.string("type");
        ev.materialWhere = ev.where;
        if (type == "box") {
            ev.kind = TimelineEvent::Kind::Box;
            ev.box = Box{e.ivec3("min"), e.ivec3("max")};
            ev.material = e.string("material");
            ev.materialWhere = e.where(e.node("material"));
        } else if (type == "sphere") {
            ev.kind = TimelineEvent::Kind::Sphere;
            ev.center = glm::vec3(e.vec3("center"));
            ev.radius = static_cast<float>(e.number("radius", 0.0, true));
            if (ev.radius <= 0.0f || ev.radius > 32768.0f)
                e.fail(e.node("radius"), "'radius' must be in (0, 32768]");
            ev.material = e.string("material");
            ev.materialWhere = e.where(e.node("material"));
        } else if (type == "voxel") {
            ev.kind = TimelineEvent::Kind::Voxel;
            ev.voxel = e.ivec3("at");
            ev.material = e.string("material");
            ev.materialWhere = e.where(e.node("material"));
        } else if (type == "light") {
            ev.kind = TimelineEvent::Kind::Light;
            ev.material = e.string("material");
            ev.materialWhere = e.where(e.node("material"));
            ev.on = e.boolean("on", true, true);
            bool hasMin = t->contains("min"), hasMax = t->contains("max");
            if (hasMin != hasMax)
                e.fail(&node,
                       "a light region needs both 'min' and 'max' (or neither: the whole world)");
            ev.wholeWorld = !hasMin;
            if (hasMin) ev.box = Box{e.ivec3("min"), e.ivec3("max")};
        } else if (type == "dynamic") {
            ev.kind = TimelineEvent::Kind::DynamicStart;
            ev.object = e.string("object");
            if (ev.object.empty()) e.fail(e.node("object"), "'object' must name a dynamic object");
        } else {
            e.fail(e.node("type"),
                   "unknown event type '{}' (known: box, sphere, voxel, light, dynamic)", type);
        }
        return ev;
    }

    std::string mSource;
};

}  // namespace

Result<Flythrough> loadFlythroughText(std::string_view text, std::string_view sourceName) {
    try {
        toml::table root = toml::parse(text, sourceName);
        return PathParser(std::string(sourceName)).parse(root);
    } catch (const toml::parse_error& e) {
        return makeError("{}:{}: {}", sourceName, e.source().begin.line, e.description());
    } catch (const ParseError& e) {
        return Error{e.message};
    }
}

Result<Flythrough> loadFlythroughFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError("{}: cannot open path file", path.string());
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return makeError("{}: read error", path.string());
    return loadFlythroughText(text.str(), path.string());
}

}  // namespace engine::world
