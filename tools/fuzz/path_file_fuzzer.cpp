// libFuzzer target for path files played as a capture plays them (tools/fuzz/run_path_fuzz.sh
// builds and runs it). Each input is read as a path file; an accepted one is played: the frame
// count and every frame's camera checked, written back and read again (the writer and the reader
// must agree), (checkFrames), the camera sampled at and past its ends,
// and the timeline bound to a small world of named materials and applied frame by frame. Paths
// longer than kMaxFuzzFrames frames are read and sampled but not played to the end: a long path
// is long work, not a defect. Any crash, sanitizer report, leak or timeout is a finding; errors
// returned as values are not.
#include <algorithm>
#include <cstdint>
#include <string_view>

#include "scene/path_file.h"
#include "scene/path_table.h"
#include "scene/scene_file.h"

namespace {

constexpr std::uint32_t kMaxFuzzFrames = 2000;

// A 32^3 world with the material names the shipped paths use, so that events bind.
constexpr std::string_view kWorld = R"(
[world]
name = "fuzz"
size = [32, 32, 32]

[[material]]
name = "stone"
albedo = [0.5, 0.5, 0.5]

[[material]]
name = "lamp"
albedo = [0.8, 0.8, 0.8]
emission = [1.0, 0.9, 0.7]
strength = 4.0

[[material]]
name = "window"
albedo = [0.7, 0.7, 0.7]
emission = [0.9, 0.9, 1.0]
strength = 2.0

[[generator]]
type = "box"
material = "stone"
min = [0, 0, 0]
max = [31, 3, 31]
)";

const engine::world::Scene& smallWorld() {
    static const engine::world::Scene scene = [] {
        auto s = engine::scene::loadSceneText(kWorld, "fuzz-world.toml");
        if (!s.ok()) __builtin_trap();  // the fixture itself must load
        return std::move(*s);
    }();
    return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    auto fly = engine::scene::loadFlythroughText(text, "fuzz-path.toml");
    if (!fly.ok()) return 0;
    engine::scene::TomlWriter out;
    engine::scene::writePath(*fly, out);
    auto again = engine::scene::loadFlythroughText(out.text(), "fuzz-written.toml");
    if (!again.ok() || again->camera.keys().size() != fly->camera.keys().size() ||
        again->timeline.events().size() != fly->timeline.events().size())
        __builtin_trap();
    const double fps = fly->fps;
    const std::uint32_t frames = fly->frameCount(fps);
    for (double t : {fly->camera.startTime() - 1.0, fly->camera.startTime(), fly->duration * 0.5,
                     fly->camera.endTime(), fly->duration, fly->duration + 1.0})
        (void)fly->camera.at(t);
    if (frames > kMaxFuzzFrames) return 0;
    (void)fly->checkFrames(fps);
    engine::world::Scene scene = smallWorld();
    if (!fly->timeline.bind(scene).ok()) return 0;
    for (std::uint32_t i = 0; i < frames; ++i) (void)fly->timeline.applyThrough(i, fps, scene);
    return 0;
}
