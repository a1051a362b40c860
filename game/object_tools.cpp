#include "game/object_tools.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <utility>

#include "game/input.h"
#include "game/world_store.h"
#include "world/scene_trace.h"
#include "world/solid_voxels.h"
#include "world/world_limits.h"

namespace game {

namespace fs = std::filesystem;
namespace world = engine::world;

engine::Result<ObjectModel> loadObjectModel(const fs::path& path) {
    const std::string ext = path.extension().string();
    std::error_code ec;
    if (ext == ".vdb" || ext == ".vox") {
        const std::uintmax_t bytes = fs::file_size(path, ec);
        if (ec)
            return engine::makeError("{}: cannot read the model: {}", path.string(), ec.message());
        if (bytes > kMaxModelFileBytes)
            return engine::makeError(
                "{}: {:.1f} MiB is too big for a model (files up to {} MiB, at most {} solid "
                "voxels)",
                path.string(), double(bytes) / (1 << 20), kMaxModelFileBytes >> 20,
                kMaxModelVoxels);
    }
    auto scene = makeWorldStore()->load(path);
    if (!scene) return scene.error();
    const world::BrickGrid& grid = scene->grid;
    const std::uint64_t solid = grid.solidVoxels();
    if (solid == 0) return engine::makeError("{}: the model has no solid voxels", path.string());
    if (solid > kMaxModelVoxels)
        return engine::makeError("{}: {} solid voxels; a model holds at most {}", path.string(),
                                 solid, kMaxModelVoxels);

    // The solid voxels and their box.
    std::vector<std::pair<glm::ivec3, world::MaterialId>> voxels;
    voxels.reserve(solid);
    world::forEachSolidVoxel(grid,
                             [&](glm::ivec3 p, world::MaterialId m) { voxels.emplace_back(p, m); });
    glm::ivec3 lo(INT32_MAX), hi(INT32_MIN);
    for (const auto& [p, m] : voxels) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p + 1);
    }
    const glm::ivec3 size = hi - lo;
    if (glm::any(glm::greaterThan(size, glm::ivec3(world::kMaxObjectExtent))))
        return engine::makeError("{}: the model spans {} x {} x {} voxels; at most {} a side",
                                 path.string(), size.x, size.y, size.z, world::kMaxObjectExtent);

    ObjectModel model;
    model.name = path.stem().string();
    model.palette = scene->palette;
    model.size = size;
    model.voxels = world::BrickGrid(size);
    for (const auto& [p, m] : voxels) model.voxels.set(p - lo, m);
    model.voxels.clearDirty();
    model.solidVoxels = solid;
    return model;
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// The world box half extents of the model turned by the nearest quarter turn to `yaw`: the box
// the position snaps by.
glm::dvec3 halfExtent(glm::ivec3 size, double yawDegrees) {
    const long quarter = std::lround(yawDegrees / 90.0);
    const glm::dvec3 s(size);
    return (quarter % 2 != 0 ? glm::dvec3(s.z, s.y, s.x) : s) * 0.5;
}

ObjectPose snapped(ObjectPose pose, glm::ivec3 size) {
    double yaw = std::remainder(pose.yawDegrees, 360.0);  // (-180, 180]
    if (yaw <= -180.0) yaw += 360.0;
    pose.yawDegrees = double(float(yaw));  // as a scene file holds it
    const glm::dvec3 half = halfExtent(size, pose.yawDegrees);
    // Halves round up at odd quarter turns and down at even ones, so a turn and its way back
    // (or four quarter turns) bring the box back where it was, not half a voxel further.
    const glm::dvec3 v = pose.position - half;
    const bool odd = std::lround(pose.yawDegrees / 90.0) % 2 != 0;
    pose.position = (odd ? glm::floor(v + 0.5) : glm::ceil(v - 0.5)) + half;
    return pose;
}

world::ObjectKey makeKey(double time, const ObjectPose& pose) {
    world::ObjectKey key;
    key.time = time;
    key.position = pose.position;
    if (pose.yawDegrees != 0.0) {
        key.given = world::ObjectKey::Given::YawPitchRoll;
        key.angles = glm::dvec3(pose.yawDegrees, 0.0, 0.0);
        key.rotation = world::rotationFromYawPitchRoll(key.angles);
    }
    return key;
}

// Sets the key at `time` (replacing one within kKeyTolerance); a static object's one key is
// moved instead unless `addKey`. A path that grows to two keys loops.
void setPose(world::DynamicObject& object, double time, const ObjectPose& pose, bool addKey) {
    std::vector<world::ObjectKey> keys = object.path.keys();
    bool loop = object.path.loop();
    if (keys.size() == 1 && (!addKey || std::abs(keys[0].time - time) <= kKeyTolerance)) {
        keys[0] = makeKey(keys[0].time, pose);
    } else {
        auto at = std::find_if(keys.begin(), keys.end(), [&](const world::ObjectKey& k) {
            return k.time >= time - kKeyTolerance;
        });
        if (at != keys.end() && std::abs(at->time - time) <= kKeyTolerance) {
            *at = makeKey(at->time, pose);
        } else {
            keys.insert(at, makeKey(time, pose));
            if (keys.size() == 2) loop = true;
        }
    }
    object.path = world::ObjectPath(std::move(keys), loop);
}

std::string describe(const world::DynamicObject& o) {
    const auto& k = o.path.keys();
    return k.size() == 1 ? "static"
                         : fmt::format("{} keys, {}", k.size(),
                                       o.path.loop() ? "looping" : "stops at the end");
}

template <typename Change>
ObjectResult modify(world::Scene& scene, UndoHistory& undo, std::size_t index, double time,
                    Change change) {
    if (index >= scene.objects.size()) return {false, "no object selected (right click one, or N)"};
    world::DynamicObject before = scene.objects[index];
    std::string label = change(scene.objects[index]);
    if (label.empty()) return {false, {}};
    const bool undoable = undo.recordObject(scene.objects, index, std::move(before), true, label);
    refreshObjects(scene, time);
    return {true, label + (undoable ? "" : " - too large to undo within the budget")};
}

}  // namespace

ObjectPose editPose(const world::DynamicObject& object, double time) {
    const auto& keys = object.path.keys();
    // Clamped by hand: a looping path wraps its last key's time to its first pose.
    const world::ObjectKey* end = time >= keys.back().time    ? &keys.back()
                                  : time <= keys.front().time ? &keys.front()
                                                              : nullptr;
    const world::RigidTransform pose =
        end ? world::RigidTransform{end->position, end->rotation} : object.path.at(time);
    const glm::dquat q = pose.rotation;
    // Objects turn about +Y only; a scene file's pitch and roll are dropped by an edit.
    const double yaw = 2.0 * std::atan2(q.y, q.w) * 180.0 / kPi;
    return snapped({pose.position, yaw}, object.modelSize);
}

ObjectResult placeObject(world::Scene& scene, UndoHistory& undo, const ObjectModel& model,
                         const Pick& target, double time) {
    if (!target.hit) return {false, "place object: nothing placed: " + missReason(target)};
    // The model's materials, by name, into the world's palette (added where missing).
    std::vector<world::MaterialId> map(model.palette.size(), world::kEmpty);
    world::DynamicObject object;
    object.modelSize = model.size;
    world::BrickGrid voxels(model.size);
    for (int z = 0; z < model.size.z; ++z)
        for (int y = 0; y < model.size.y; ++y)
            for (int x = 0; x < model.size.x; ++x) {
                const world::MaterialId m = model.voxels.get({x, y, z});
                if (m == world::kEmpty) continue;
                if (map[m] == world::kEmpty) {
                    const world::Material& mat = model.palette[m];
                    auto id = scene.palette.find(mat.name);
                    if (!id) id = scene.palette.add(mat);
                    if (!id)
                        return {false,
                                fmt::format("place object: the palette is full ({} materials)",
                                            scene.palette.size())};
                    map[m] = *id;
                }
                voxels.set({x, y, z}, map[m]);
            }
    voxels.clearDirty();
    object.model = std::make_shared<const world::BrickGrid>(std::move(voxels));

    // Lowest corner on the voxel in front of the face, centred across the face.
    glm::ivec3 corner = target.adjacent() - model.size / 2;
    for (int a = 0; a < 3; ++a) {
        if (target.normal[a] > 0) corner[a] = target.adjacent()[a];
        if (target.normal[a] < 0) corner[a] = target.adjacent()[a] - (model.size[a] - 1);
    }
    ObjectPose pose{glm::dvec3(corner) + glm::dvec3(model.size) * 0.5, 0.0};
    object.path = world::ObjectPath({makeKey(time, pose)}, false);
    for (int n = int(scene.objects.size()) + 1;; ++n) {
        object.name = fmt::format("{}_{}", model.name, n);
        if (std::none_of(scene.objects.begin(), scene.objects.end(),
                         [&](const world::DynamicObject& o) { return o.name == object.name; }))
            break;
    }
    std::string label = fmt::format("place {} ({} voxels) at {} {} {}", object.name,
                                    model.solidVoxels, corner.x, corner.y, corner.z);
    scene.objects.push_back(std::move(object));
    const bool undoable =
        undo.recordObject(scene.objects, scene.objects.size() - 1, std::nullopt, true, label);
    refreshObjects(scene, time);
    return {true, label + (undoable ? "" : " - too large to undo within the budget")};
}

ObjectResult moveObject(world::Scene& scene, UndoHistory& undo, std::size_t index, glm::ivec3 delta,
                        double time) {
    return modify(scene, undo, index, time, [&](world::DynamicObject& o) {
        ObjectPose pose = editPose(o, time);
        pose.position += glm::dvec3(delta);
        setPose(o, time, pose, false);
        return fmt::format("move {} by {} {} {} ({})", o.name, delta.x, delta.y, delta.z,
                           describe(o));
    });
}

ObjectResult turnObject(world::Scene& scene, UndoHistory& undo, std::size_t index, double degrees,
                        double time) {
    return modify(scene, undo, index, time, [&](world::DynamicObject& o) {
        ObjectPose pose = editPose(o, time);
        pose.yawDegrees += degrees;
        pose = snapped(pose, o.modelSize);
        setPose(o, time, pose, false);
        return fmt::format("turn {} to {:g} degrees ({})", o.name, pose.yawDegrees, describe(o));
    });
}

ObjectResult setObjectKey(world::Scene& scene, UndoHistory& undo, std::size_t index, double time) {
    return modify(scene, undo, index, time, [&](world::DynamicObject& o) {
        setPose(o, time, editPose(o, time), true);
        return fmt::format("key {} at {:.2f} s ({})", o.name, time, describe(o));
    });
}

ObjectResult clearObjectPath(world::Scene& scene, UndoHistory& undo, std::size_t index,
                             double time) {
    return modify(scene, undo, index, time, [&](world::DynamicObject& o) {
        o.path = world::ObjectPath({makeKey(time, editPose(o, time))}, false);
        o.startTime.reset();
        return fmt::format("clear the path of {} (static)", o.name);
    });
}

ObjectResult toggleObjectLoop(world::Scene& scene, UndoHistory& undo, std::size_t index,
                              double time) {
    if (index < scene.objects.size() && scene.objects[index].path.keys().size() < 2)
        return {false, scene.objects[index].name + " has no path to loop (K sets keys)"};
    return modify(scene, undo, index, time, [&](world::DynamicObject& o) {
        o.path = world::ObjectPath(o.path.keys(), !o.path.loop());
        return fmt::format("{} {}", o.name, o.path.loop() ? "loops" : "stops at its last key");
    });
}

ObjectResult deleteObject(world::Scene& scene, UndoHistory& undo, std::size_t index, double time) {
    if (index >= scene.objects.size()) return {false, "no object selected (right click one, or N)"};
    world::DynamicObject gone = std::move(scene.objects[index]);
    scene.objects.erase(scene.objects.begin() + std::ptrdiff_t(index));
    std::string label = "delete " + gone.name;
    undo.recordObject(scene.objects, index, std::move(gone), false, label);
    refreshObjects(scene, time);
    return {true, label};
}

bool dragObject(world::DynamicObject& object, const Pick& target, double time) {
    if (!target.hit) return false;
    ObjectPose pose = editPose(object, time);
    const glm::dvec3 half = halfExtent(object.modelSize, pose.yawDegrees);
    const glm::ivec3 extent(glm::round(half * 2.0));
    const glm::ivec3 corner = target.adjacent() - extent / 2;
    const glm::dvec3 to(corner.x + half.x, pose.position.y, corner.z + half.z);
    if (to == pose.position) return false;
    pose.position = to;
    setPose(object, time, pose, false);
    return true;
}

std::optional<std::size_t> pickObject(const world::Scene& scene, glm::vec3 origin,
                                      glm::vec3 direction) {
    const float finite = glm::dot(origin, origin) + glm::dot(direction, direction);
    if (!std::isfinite(finite) || glm::dot(direction, direction) == 0.0f) return std::nullopt;
    const world::SceneHit hit =
        world::traceScene(scene.grid, &scene.dynamic, origin, direction, kPickDistance);
    if (!hit.hit || !hit.dynamicSet) return std::nullopt;
    // The same test voxelizeObjects makes: the voxel's centre in the model; first object wins.
    const glm::dvec4 centre(glm::dvec3(hit.voxel) + 0.5, 1.0);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const world::DynamicObject& o = scene.objects[i];
        const glm::ivec3 m(
            glm::floor(glm::dvec3(glm::inverse(o.worldFromModel(o.current)) * centre)));
        if (world::Box{glm::ivec3(0), o.modelSize}.contains(m) && o.model->get(m) != world::kEmpty)
            return i;
    }
    return std::nullopt;
}

void refreshObjects(world::Scene& scene, double time) {
    for (world::DynamicObject& o : scene.objects) o.current = o.poseAt(time);
    const std::uint64_t revision = scene.dynamic.revision;
    scene.dynamic = world::voxelizeObjects(scene.objects);
    scene.dynamic.revision = revision + 1;
}

ObjectResult ObjectTools::handle(const InputState& input, bool mouseLook, const Pick& target,
                                 glm::vec3 origin, glm::vec3 direction, world::Scene& scene,
                                 UndoHistory& undo, double time) {
    ObjectResult r;
    auto add = [&](ObjectResult x) {
        r.changed |= x.changed;
        if (!x.message.empty()) r.message = std::move(x.message);
    };
    if (mDrag && !input.buttonHeld(GLFW_MOUSE_BUTTON_LEFT)) add(finishDrag(scene, undo));
    if (mDrag && mDrag->index < scene.objects.size() &&
        dragObject(scene.objects[mDrag->index], target, mDrag->time))
        refreshObjects(scene, time);
    const bool leftPressed = mouseLook && input.buttonPressed(GLFW_MOUSE_BUTTON_LEFT);
    if (leftPressed && selected && pickObject(scene, origin, direction) == selected) {
        mDrag = Drag{*selected, scene.objects[*selected], time};
        add({false, "dragging " + scene.objects[*selected].name + " (release to drop)"});
    } else if (leftPressed) {
        if (models.empty()) {
            add({false,
                 "no model to place: start vox play with --model FILE.vox|FILE.vdb|WORLD.toml"});
        } else {
            ObjectResult placed = placeObject(scene, undo, models[model], target, time);
            if (placed.changed) selected = scene.objects.size() - 1;
            add(std::move(placed));
        }
    }
    if (mouseLook && input.buttonPressed(GLFW_MOUSE_BUTTON_RIGHT)) {
        selected = pickObject(scene, origin, direction);
        add({false, selected ? "selected " + scene.objects[*selected].name
                             : "no object under the crosshair"});
    }
    if (input.pressed(GLFW_KEY_N)) {
        if (scene.objects.empty()) {
            selected.reset();
            add({false, "no objects to select"});
        } else {
            selected = selected ? (*selected + 1) % scene.objects.size() : 0;
            add({false, "selected " + scene.objects[*selected].name});
        }
    }
    if (input.pressed(GLFW_KEY_M) && !models.empty()) {
        model = (model + 1) % models.size();
        add({false, "model: " + models[model].name});
    }
    if (!selected) return r;
    const std::size_t i = *selected;
    const int step = input.shift() ? 8 : 1;
    const std::pair<int, glm::ivec3> moves[] = {
        {GLFW_KEY_LEFT, {-step, 0, 0}}, {GLFW_KEY_RIGHT, {step, 0, 0}},
        {GLFW_KEY_UP, {0, 0, step}},    {GLFW_KEY_DOWN, {0, 0, -step}},
        {GLFW_KEY_HOME, {0, step, 0}},  {GLFW_KEY_END, {0, -step, 0}}};
    for (const auto& [key, delta] : moves) {
        if (input.pressed(key)) add(moveObject(scene, undo, i, delta, time));
    }
    if (input.pressed(GLFW_KEY_R))
        add(turnObject(scene, undo, i, input.shift() ? -90.0 : 90.0, time));
    if (input.pressed(GLFW_KEY_LEFT_BRACKET))
        add(turnObject(scene, undo, i, -kFreeTurnDegrees, time));
    if (input.pressed(GLFW_KEY_RIGHT_BRACKET))
        add(turnObject(scene, undo, i, kFreeTurnDegrees, time));
    if (input.pressed(GLFW_KEY_K)) add(setObjectKey(scene, undo, i, time));
    if (input.pressed(GLFW_KEY_L)) add(toggleObjectLoop(scene, undo, i, time));
    if (input.pressed(GLFW_KEY_BACKSPACE)) add(clearObjectPath(scene, undo, i, time));
    if (input.pressed(GLFW_KEY_DELETE)) {
        add(deleteObject(scene, undo, i, time));
        selected.reset();
    }
    return r;
}

ObjectResult ObjectTools::finishDrag(world::Scene& scene, UndoHistory& undo) {
    if (!mDrag) return {};
    Drag drag = std::move(*mDrag);
    mDrag.reset();
    if (drag.index >= scene.objects.size()) return {};
    const world::DynamicObject& o = scene.objects[drag.index];
    const ObjectPose from = editPose(drag.before, drag.time), to = editPose(o, drag.time);
    if (from.position == to.position) return {false, "drag: " + o.name + " stayed where it was"};
    const glm::ivec3 d(glm::round(to.position - from.position));
    std::string label = fmt::format("drag {} by {} {} {} ({})", o.name, d.x, d.y, d.z, describe(o));
    const bool undoable =
        undo.recordObject(scene.objects, drag.index, std::move(drag.before), true, label);
    return {true, label + (undoable ? "" : " - too large to undo within the budget")};
}

void ObjectTools::objectsChanged(const world::Scene& scene) {
    if (selected && *selected >= scene.objects.size()) selected.reset();
}

std::string ObjectTools::status(const world::Scene& scene) const {
    std::string s = models.empty() ? "object tool: no model (--model FILE)"
                                   : fmt::format("object tool: model {} ({} voxels, M: next)",
                                                 models[model].name, models[model].solidVoxels);
    if (selected && *selected < scene.objects.size()) {
        const world::DynamicObject& o = scene.objects[*selected];
        s += fmt::format("; selected {} ({})", o.name, describe(o));
    } else {
        s += fmt::format("; {} object(s), none selected", scene.objects.size());
    }
    return s;
}

}  // namespace game
