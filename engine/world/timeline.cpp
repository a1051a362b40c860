#include "world/timeline.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"
#include "world/world_edits.h"

namespace engine::world {

Timeline::Timeline(std::vector<TimelineEvent> events) : mEvents(std::move(events)) {
    std::stable_sort(
        mEvents.begin(), mEvents.end(),
        [](const TimelineEvent& a, const TimelineEvent& b) { return a.time < b.time; });
}

std::uint32_t Timeline::firstFrame(double time, double fps) {
    CHECK(fps > 0.0);
    if (time <= 0.0) return 0;
    // The tolerance keeps t = 0.1 s at 30 fps on frame 3, not 4 (0.1 * 30 = 3.0000000000000004).
    return static_cast<std::uint32_t>(std::ceil(time * fps - 1e-6));
}

Status Timeline::bind(Scene& scene) {
    auto lookup = [&](const TimelineEvent& e, const std::string& name) -> Result<MaterialId> {
        if (name == "empty" || name == "air") return kEmpty;
        if (auto id = scene.palette.find(name)) return *id;
        return makeError("{}: unknown material '{}'", e.materialWhere, name);
    };
    const Box world = scene.grid.bounds();
    for (TimelineEvent& e : mEvents) {
        switch (e.kind) {
            case TimelineEvent::Kind::Box: {
                if (e.box.empty())
                    return makeError("{}: box is empty (max must exceed min on every axis)",
                                     e.where);
                if (e.box.intersect(world).empty())
                    return makeError("{}: box lies outside the world", e.where);
                auto m = lookup(e, e.material);
                if (!m) return m.error();
                e.to = *m;
                break;
            }
            case TimelineEvent::Kind::Sphere: {
                auto m = lookup(e, e.material);
                if (!m) return m.error();
                e.to = *m;
                break;
            }
            case TimelineEvent::Kind::Voxel: {
                if (!world.contains(e.voxel))
                    return makeError("{}: voxel ({}, {}, {}) is outside the world", e.where,
                                     e.voxel.x, e.voxel.y, e.voxel.z);
                auto m = lookup(e, e.material);
                if (!m) return m.error();
                e.to = *m;
                break;
            }
            case TimelineEvent::Kind::Light: {
                auto m = lookup(e, e.material);
                if (!m) return m.error();
                if (*m == kEmpty || !scene.palette[*m].emissive())
                    return makeError("{}: material '{}' does not emit light", e.materialWhere,
                                     e.material);
                if (e.wholeWorld) e.box = world;
                if (e.box.empty())
                    return makeError("{}: light region is empty (max must exceed min)", e.where);
                // The dark twin: same surface, no emission. Found or added once per material.
                std::string twinName = e.material + ".off";
                std::optional<MaterialId> twin = scene.palette.find(twinName);
                if (!twin) {
                    Material dark = scene.palette[*m];
                    dark.name = twinName;
                    dark.emissionColor = glm::vec3(0.0f);
                    dark.emissionStrength = 0.0f;
                    twin = scene.palette.add(dark);
                    if (!twin) return makeError("{}: the palette is full", e.where);
                }
                e.from = e.on ? *twin : *m;
                e.to = e.on ? *m : *twin;
                break;
            }
            case TimelineEvent::Kind::DynamicStart: {
                // The start is part of the object's pose function from now on, so any frame —
                // also one of a slice rendered elsewhere — poses it the same way.
                DynamicObject* object = nullptr;
                std::string names;
                for (DynamicObject& o : scene.objects) {
                    if (o.name == e.object) object = &o;
                    names += (names.empty() ? "" : ", ") + o.name;
                }
                if (!object)
                    return makeError("{}: no dynamic object named '{}' (the scene has: {})",
                                     e.where, e.object, names.empty() ? "none" : names);
                object->startTime = std::min(object->startTime.value_or(e.time), e.time);
                break;
            }
        }
    }
    mBound = true;
    return {};
}

std::uint32_t Timeline::applyThrough(std::uint32_t frame, double fps, Scene& scene) {
    CHECK_MSG(mBound || mEvents.empty(), "Timeline::bind must run before applyThrough");
    std::uint32_t count = 0;
    while (mNext < mEvents.size() && firstFrame(mEvents[mNext].time, fps) <= frame) {
        apply(mEvents[mNext++], scene);
        ++count;
    }
    return count;
}

void Timeline::apply(const TimelineEvent& e, Scene& scene) {
    switch (e.kind) {
        case TimelineEvent::Kind::Box:
            fillBox(scene.grid, e.box.intersect(scene.grid.bounds()), e.to);
            break;
        case TimelineEvent::Kind::Sphere:
            fillSphere(scene.grid, e.center, e.radius, e.to);
            break;
        case TimelineEvent::Kind::Voxel:
            scene.grid.set(e.voxel, e.to);
            break;
        case TimelineEvent::Kind::Light:
            replaceMaterial(scene.grid, e.box.intersect(scene.grid.bounds()), e.from, e.to);
            break;
        case TimelineEvent::Kind::DynamicStart:
            break;  // bound into the object's pose (DynamicObject::startTime)
    }
}

}  // namespace engine::world
