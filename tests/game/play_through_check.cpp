// Checks a scripted `vox play` run (tests/game/play_through_test.sh) against the CPU:
//  1. replays the edit log on the original world with the reference traversal (its own pick
//     from each logged crosshair ray, its own voxel writes, its own undo stack) and requires
//     the saved world to equal the result voxel for voxel;
//  2. renders the original and the saved world headless at the screenshot's view and requires
//     the sandbox's screenshot to equal the saved world's render exactly, and to differ from
//     the original's only at pixels that see (or are shadowed by) voxels within a few voxels
//     of an edit.
// Usage: play_through_check ORIGINAL SAVED EDIT_LOG SCREENSHOT PLACES REMOVES PAINTS UNDOS
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "check_expect.h"
#include "core/log.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "render/renderer.h"
#include "scene/scene_file.h"
#include "world/ray_traversal.h"

using namespace engine::world;
using namespace engine::scene;

namespace {

constexpr float kNearVoxels = 3.0f;  // a single voxel's shadow on the ground lies this close

struct Change {
    glm::ivec3 voxel;
    MaterialId before, after;
};

struct View {
    CameraPreset camera;
    glm::uvec2 size{0};
    float exposure = 1.0f;
    std::string path;
    std::string lighting;
};

Scene load(const char* path) {
    auto scene = loadSceneFile(path);
    if (!scene) {
        std::printf("FAIL: %s\n", scene.error().message.c_str());
        std::exit(1);
    }
    return std::move(*scene);
}

std::vector<glm::ivec3> changedVoxels(const BrickGrid& a, const BrickGrid& b) {
    std::vector<glm::ivec3> out;
    glm::ivec3 cells = a.sizeInCells();
    for (int cz = 0; cz < cells.z; ++cz)
        for (int cy = 0; cy < cells.y; ++cy)
            for (int cx = 0; cx < cells.x; ++cx) {
                glm::ivec3 c(cx, cy, cz);
                if (!BrickGrid::cellIsBrick(a.cell(c)) && a.cell(c) == b.cell(c)) continue;
                BrickVoxels va = a.readCell(c), vb = b.readCell(c);
                for (int i = 0; i < kBrickVoxels; ++i) {
                    if (va[i] != vb[i]) out.push_back(c * kBrickDim + brickVoxelPosition(i));
                }
            }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 9) {
        std::fprintf(stderr,
                     "usage: %s ORIGINAL SAVED EDIT_LOG SCREENSHOT PLACES REMOVES PAINTS UNDOS\n",
                     argv[0]);
        return 2;
    }
    engine::log::init();
    Scene original = load(argv[1]);
    Scene saved = load(argv[2]);
    int want[4] = {std::atoi(argv[5]), std::atoi(argv[6]), std::atoi(argv[7]), std::atoi(argv[8])};
    int got[4] = {0, 0, 0, 0};  // places, removes, paints, undos

    // 1. Replay the log on the CPU.
    BrickGrid expected = original.grid;
    std::vector<Change> done, undone;
    View view;
    std::ifstream log(argv[3]);
    for (std::string line; std::getline(log, line);) {
        std::istringstream in(line);
        std::string kind, word;
        std::uint64_t frame = 0;
        in >> kind >> frame;
        if (kind == "edit") {
            std::string tool, brush;
            glm::vec3 o, d;
            glm::ivec3 lo, hi;
            int material = 0;
            in >> tool >> brush >> word >> o.x >> o.y >> o.z >> d.x >> d.y >> d.z >> word >> lo.x >>
                lo.y >> lo.z >> hi.x >> hi.y >> hi.z;
            for (int i = 0; i < 5; ++i) in >> word;  // sphere cx cy cz r
            in >> word >> material;
            EXPECT(brush == "voxel", "frame %llu: the check replays single-voxel edits only",
                   (unsigned long long)frame);
            RayHit hit = traceRay(expected, Ray{o, glm::normalize(d), 1024.0f});
            EXPECT(hit.hit, "frame %llu: the logged ray hits nothing", (unsigned long long)frame);
            if (!hit.hit) continue;
            glm::ivec3 v = tool == "place" ? hit.voxel + faceNormal(hit.face) : hit.voxel;
            EXPECT(v == lo && hi == lo + 1,
                   "frame %llu: %s at (%d, %d, %d) but the CPU pick says (%d, %d, %d)",
                   (unsigned long long)frame, tool.c_str(), lo.x, lo.y, lo.z, v.x, v.y, v.z);
            MaterialId after = tool == "remove" ? kEmpty : MaterialId(material);
            if (tool == "paint" && expected.get(v) == kEmpty) after = kEmpty;
            done.push_back({v, expected.get(v), after});
            undone.clear();
            expected.set(v, after);
            got[tool == "place" ? 0 : tool == "remove" ? 1 : 2]++;
        } else if (kind == "undo") {
            EXPECT(!done.empty(), "frame %llu: undo with nothing to undo",
                   (unsigned long long)frame);
            if (done.empty()) continue;
            expected.set(done.back().voxel, done.back().before);
            undone.push_back(done.back());
            done.pop_back();
            got[3]++;
        } else if (kind == "redo") {
            if (undone.empty()) continue;
            expected.set(undone.back().voxel, undone.back().after);
            done.push_back(undone.back());
            undone.pop_back();
        } else if (kind == "screenshot") {
            in >> view.path >> word >> view.camera.position.x >> view.camera.position.y >>
                view.camera.position.z >> view.camera.target.x >> view.camera.target.y >>
                view.camera.target.z >> word >> view.camera.fovYDegrees >> word >> view.size.x >>
                view.size.y >> word >> frame >> word >> view.exposure >> word >> view.lighting;
        }
    }
    const char* names[4] = {"places", "removes", "paints", "undos"};
    for (int i = 0; i < 4; ++i)
        EXPECT(got[i] == want[i], "%d %s in the log, expected %d", got[i], names[i], want[i]);
    std::vector<glm::ivec3> edits = changedVoxels(original.grid, saved.grid);
    EXPECT(saved.grid == expected, "the saved world differs from the edits replayed on the CPU");
    std::printf(
        "edit log: %d places, %d removes, %d paints, %d undos; saved world %s the CPU replay; %zu "
        "voxels differ "
        "from the original\n",
        got[0], got[1], got[2], got[3], saved.grid == expected ? "equals" : "DIFFERS FROM",
        edits.size());

    // 2. The screenshot against headless renders of both worlds at its view.
    EXPECT(view.size.x > 0, "no screenshot in the edit log");
    // A pixel-exact comparison needs a deterministic method (ReSTIR's image depends on history).
    EXPECT(view.lighting == "preview",
           "the screenshot was lit with '%s'; run the sandbox with --method preview",
           view.lighting.c_str());
    auto shot = engine::io::readPng(argv[4]);
    if (!shot || view.size.x == 0) {
        if (!shot) std::printf("FAIL: %s\n", shot.error().message.c_str());
        return 1;
    }
    engine::gpu::ContextOptions options;
    options.validation = true;
    auto ctx = engine::gpu::Context::create(options);
    if (!ctx) {
        std::printf("FAIL: %s\n", ctx.error().message.c_str());
        return 1;
    }
    engine::render::FrameSettings settings;
    settings.width = view.size.x;
    settings.height = view.size.y;
    settings.exposure = view.exposure;
    engine::lighting::LightingSettings lighting;
    lighting.method = engine::lighting::Method::Preview;
    engine::render::Renderer renderer(**ctx);
    renderer.render(original, view.camera, settings, lighting);
    engine::render::FrameImages before = renderer.readback();
    engine::render::Renderer rendererSaved(**ctx);
    rendererSaved.render(saved, view.camera, settings, lighting);
    engine::render::FrameImages after = rendererSaved.readback();

    EXPECT(shot->width == view.size.x && shot->height == view.size.y,
           "screenshot is %ux%u, the log says %ux%u", shot->width, shot->height, view.size.x,
           view.size.y);
    if (shot->rgba8.size() != after.rgba8.size()) return 1;
    std::size_t notSaved = 0, differing = 0, far = 0;
    float farthest = 0.0f;
    auto distanceToEdit = [&](const shared::GBufferTexel& t) {
        if (t.voxel.w >= 6) return 1e9f;  // the sky
        float best = 1e9f;
        for (glm::ivec3 e : edits)
            best = std::min(best, glm::length(glm::vec3(glm::ivec3(t.voxel) - e)));
        return best;
    };
    for (std::size_t i = 0; i < shot->rgba8.size(); ++i) {
        notSaved += shot->rgba8[i] != after.rgba8[i];
        if (shot->rgba8[i] == before.rgba8[i]) continue;
        ++differing;
        float d = std::min(distanceToEdit(before.gbuffer[i]), distanceToEdit(after.gbuffer[i]));
        farthest = std::max(farthest, d);
        far += d > kNearVoxels;
    }
    EXPECT(notSaved == 0, "%zu screenshot pixels differ from a render of the saved world",
           notSaved);
    EXPECT(differing > 0, "the screenshot shows no edit");
    EXPECT(far == 0, "%zu changed pixels are farther than %.0f voxels from every edit", far,
           double(kNearVoxels));
    std::printf(
        "screenshot %ux%u: equals the saved world's render (%zu pixels differ); %zu pixels differ "
        "from the "
        "original's render, %zu of them farther than %.0f voxels from an edit (farthest %.2f)\n",
        shot->width, shot->height, notSaved, differing, far, double(kNearVoxels), double(farthest));
    EXPECT((*ctx)->validationErrors() == 0, "%u Vulkan validation errors",
           (*ctx)->validationErrors());
    std::printf("%s\n", failures ? "play-through check FAILED" : "play-through check passed");
    return failures ? 1 : 0;
}
