// The [path] reader and writer of scene/path_file.h.
#include "scene/path_file.h"

#include <string>
#include <vector>

#include "scene/path_table.h"
#include "world/scene.h"

namespace engine::scene {

namespace {

// Key and event times, and the duration: a path lasts at most a day.
constexpr NumberRange kPathTimeRange = closedRange(0.0, 24.0 * 3600.0, "s");

using world::CameraKey;
using world::TimelineEvent;

CameraKey readKey(const toml::node& node, const std::vector<CameraKey>& previous,
                  std::string_view source) {
    const toml::table* t = node.as_table();
    if (!t) throw ParseError{std::string(source) + ": each [[path.key]] must be a table"};
    KeyReader k(source, *t);
    CameraKey key;
    key.time = k.number("time", 0.0, kPathTimeRange, true);
    key.position = k.vec3("position", {}, world::kCoordinateRange, true);
    key.target = k.vec3("target", {}, world::kCoordinateRange, true);
    key.fovYDegrees = static_cast<float>(
        k.number("fov", previous.empty() ? 60.0 : previous.back().fovYDegrees, world::kFovRange));
    if (!previous.empty() && key.time <= previous.back().time)
        k.fail(k.node("time"), "key times must increase: {} s after {} s", key.time,
               previous.back().time);
    if (glm::length(key.target - key.position) < 1e-3f)
        k.fail(&node, "key target equals its position");
    k.finish();
    return key;
}

TimelineEvent readEvent(const toml::node& node, double duration, std::string_view source) {
    const toml::table* t = node.as_table();
    if (!t) throw ParseError{std::string(source) + ": each [[path.event]] must be a table"};
    KeyReader e(source, *t);
    TimelineEvent ev;
    ev.where = e.where(&node);
    ev.time = e.number("time", 0.0, kPathTimeRange, true);
    if (ev.time < 0.0 || ev.time > duration)
        e.fail(e.node("time"), "event time {} s is outside the path's 0..{} s", ev.time, duration);
    std::string type = e.string("type");
    ev.materialWhere = ev.where;
    auto material = [&] {
        ev.material = e.string("material");
        ev.materialWhere = e.where(e.node("material"));
    };
    if (type == "box") {
        ev.kind = TimelineEvent::Kind::Box;
        ev.box = world::Box{e.ivec3("min", {}, kVoxelIndexRange, true),
                            e.ivec3("max", {}, kVoxelIndexRange, true)};
        material();
    } else if (type == "sphere") {
        ev.kind = TimelineEvent::Kind::Sphere;
        ev.center = e.vec3("center", {}, world::kCoordinateRange, true);
        ev.radius =
            static_cast<float>(e.number("radius", 0.0, aboveRange(0.0, 32768.0, "voxels"), true));
        material();
    } else if (type == "voxel") {
        ev.kind = TimelineEvent::Kind::Voxel;
        ev.voxel = e.ivec3("at", {}, kVoxelIndexRange, true);
        material();
    } else if (type == "light") {
        ev.kind = TimelineEvent::Kind::Light;
        material();
        ev.on = e.boolean("on", true, true);
        bool hasMin = t->contains("min"), hasMax = t->contains("max");
        if (hasMin != hasMax)
            e.fail(&node,
                   "a light region needs both 'min' and 'max' (or neither: the whole world)");
        ev.wholeWorld = !hasMin;
        if (hasMin)
            ev.box = world::Box{e.ivec3("min", {}, kVoxelIndexRange, true),
                                e.ivec3("max", {}, kVoxelIndexRange, true)};
    } else if (type == "dynamic") {
        ev.kind = TimelineEvent::Kind::DynamicStart;
        ev.object = e.string("object");
        if (ev.object.empty()) e.fail(e.node("object"), "'object' must name a dynamic object");
    } else {
        e.fail(e.node("type"),
               "unknown event type '{}' (known: box, sphere, voxel, light, dynamic)", type);
    }
    e.finish();
    return ev;
}

void writeEvent(const TimelineEvent& ev, TomlWriter& out) {
    out.arrayTable("path.event");
    out.key("time", ev.time);
    switch (ev.kind) {
        case TimelineEvent::Kind::Box:
            out.key("type", "box");
            out.key("min", ev.box.min);
            out.key("max", ev.box.max);
            out.key("material", ev.material);
            break;
        case TimelineEvent::Kind::Sphere:
            out.key("type", "sphere");
            out.key("center", ev.center);
            out.key("radius", ev.radius);
            out.key("material", ev.material);
            break;
        case TimelineEvent::Kind::Voxel:
            out.key("type", "voxel");
            out.key("at", ev.voxel);
            out.key("material", ev.material);
            break;
        case TimelineEvent::Kind::Light:
            out.key("type", "light");
            out.key("material", ev.material);
            out.key("on", ev.on);
            if (!ev.wholeWorld) {
                out.key("min", ev.box.min);
                out.key("max", ev.box.max);
            }
            break;
        case TimelineEvent::Kind::DynamicStart:
            out.key("type", "dynamic");
            out.key("object", ev.object);
            break;
    }
}

}  // namespace

world::Flythrough readPath(const toml::table& t, std::string_view source) {
    KeyReader path(source, t);
    world::Flythrough fly;
    fly.source = std::string(source);
    fly.fps = path.number("fps", 30.0, world::kFpsRange);

    std::vector<CameraKey> keys;
    const toml::node* k = path.node("key");
    const toml::array* ka = k ? k->as_array() : nullptr;
    if (!ka || ka->empty())
        path.fail(k ? k : &t, "[path] needs at least one camera key ([[path.key]])");
    for (const toml::node& key : *ka) keys.push_back(readKey(key, keys, source));

    double lastKey = keys.back().time;
    fly.duration = path.number("duration", lastKey, kPathTimeRange);
    if (fly.duration < lastKey)
        path.fail(path.node("duration"),
                  "'duration' must be at least the last key's time ({} s) and at most a day",
                  lastKey);
    fly.camera = world::CameraPath(std::move(keys));

    std::vector<TimelineEvent> events;
    if (const toml::node* e = path.node("event")) {
        const toml::array* ea = e->as_array();
        if (!ea) path.fail(e, "'event' must be an array of tables ([[path.event]])");
        for (const toml::node& event : *ea)
            events.push_back(readEvent(event, fly.duration, source));
    }
    fly.timeline = world::Timeline(std::move(events));
    path.finish();
    return fly;
}

void writePath(const world::Flythrough& fly, TomlWriter& out) {
    out.table("path");
    out.key("fps", fly.fps);
    out.key("duration", fly.duration);
    for (const CameraKey& key : fly.camera.keys()) {
        out.arrayTable("path.key");
        out.key("time", key.time);
        out.key("position", key.position);
        out.key("target", key.target);
        out.key("fov", key.fovYDegrees);
    }
    for (const TimelineEvent& ev : fly.timeline.events()) writeEvent(ev, out);
}

Result<world::Flythrough> loadFlythroughText(std::string_view text, std::string_view sourceName) {
    std::string source(sourceName);
    return parseToml<world::Flythrough>(text, sourceName, [&](const toml::table& root) {
        KeyReader top(source, root);
        // A scene file's other tables are the scene loader's business; a path file has only [path].
        if (root.contains("world")) top.acceptAll();
        const toml::node* n = top.node("path");
        if (!n) top.fail(nullptr, "no [path] table (camera keys and events for vox capture)");
        const toml::table* t = n->as_table();
        if (!t) top.fail(n, "'path' must be a table ([path])");
        world::Flythrough fly = readPath(*t, source);
        top.finish();
        return fly;
    });
}

Result<world::Flythrough> loadFlythroughFile(const std::filesystem::path& path) {
    auto text = readTextFile(path, "path file");
    if (!text) return text.error();
    return loadFlythroughText(*text, path.string());
}

}  // namespace engine::scene
