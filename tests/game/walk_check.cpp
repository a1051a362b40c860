// Checks the walk log of a scripted `vox play --walk-log` run (tests/game/walk_test.sh) against
// the CPU grid: in every walk frame the player's box overlaps no solid voxel of the world nor of
// the dynamic objects posed at that frame's time (voxel by voxel through BrickGrid::get), and
// stays inside the world's sides. Then what the walk in tests/game/walk_world.toml must show: it
// climbed the one-voxel terrace, never passed the two-voxel wall at z = 44, rode the raft a long
// way, jumped, and crouched with a lower box.
// Usage: walk_check WORLD WALK_LOG
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "check_expect.h"
#include "scene/scene_file.h"
#include "world/dynamic_grid.h"

using namespace engine::world;

namespace {

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream s(line);
    std::string field;
    while (std::getline(s, field, ',')) out.push_back(field);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::printf("usage: walk_check WORLD WALK_LOG\n");
        return 2;
    }
    auto loaded = engine::scene::loadSceneFile(argv[1]);
    if (!loaded) {
        std::printf("FAIL: %s\n", loaded.error().message.c_str());
        return 1;
    }
    Scene scene = std::move(*loaded);
    std::ifstream log(argv[2]);
    std::string line;
    std::getline(log, line);
    EXPECT(line.rfind(
               "frame,time,mode,min_x,min_y,min_z,max_x,max_y,max_z,on_ground,crouching,support",
               0) == 0,
           "walk log header: %s", line.c_str());
    const glm::ivec3 size = scene.grid.sizeInVoxels();
    int walkFrames = 0, flyFrames = 0, raftFrames = 0, crouchFrames = 0;
    double raftMinX = 1e9, raftMaxX = -1e9, highestOnTerrace = 0.0, highestNearWall = 0.0,
           farthestZ = 0.0;
    bool crouchLower = true;
    while (std::getline(log, line)) {
        const std::vector<std::string> f = split(line);
        if (f.size() < 14) {
            EXPECT(false, "short walk log row: %s", line.c_str());
            continue;
        }
        if (f[2] == "fly") {
            ++flyFrames;
            continue;
        }
        ++walkFrames;
        const double time = std::strtod(f[1].c_str(), nullptr);
        const glm::dvec3 lo(std::strtod(f[3].c_str(), nullptr), std::strtod(f[4].c_str(), nullptr),
                            std::strtod(f[5].c_str(), nullptr));
        const glm::dvec3 hi(std::strtod(f[6].c_str(), nullptr), std::strtod(f[7].c_str(), nullptr),
                            std::strtod(f[8].c_str(), nullptr));
        // The objects as that frame drew them.
        updateDynamicObjects(scene.objects, scene.dynamic, time, time);
        for (int z = int(std::floor(lo.z)); z < hi.z; ++z)
            for (int y = int(std::floor(lo.y)); y < hi.y; ++y)
                for (int x = int(std::floor(lo.x)); x < hi.x; ++x) {
                    if (!(x + 1 > lo.x && y + 1 > lo.y && z + 1 > lo.z)) continue;
                    const glm::ivec3 v(x, y, z);
                    EXPECT(scene.grid.get(v) == kEmpty,
                           "frame %s: the player's box overlaps static voxel (%d, %d, %d)",
                           f[0].c_str(), x, y, z);
                    EXPECT(scene.dynamic.get(v) == kEmpty,
                           "frame %s: the player's box overlaps object voxel (%d, %d, %d)",
                           f[0].c_str(), x, y, z);
                }
        EXPECT(lo.x >= 0.0 && lo.z >= 0.0 && lo.y >= 0.0 && hi.x <= size.x && hi.z <= size.z,
               "frame %s: the player left the world", f[0].c_str());
        farthestZ = std::max(farthestZ, hi.z);
        if (f[11] == "raft") {
            ++raftFrames;
            raftMinX = std::min(raftMinX, lo.x);
            raftMaxX = std::max(raftMaxX, lo.x);
        } else if (lo.z >= 24.0) {
            highestOnTerrace = std::max(highestOnTerrace, lo.y);
            if (hi.z > 43.0) highestNearWall = std::max(highestNearWall, lo.y);
        }
        if (f[10] == "1") {
            ++crouchFrames;
            crouchLower &= std::abs((hi.y - lo.y) - 1.5) < 1e-6;
        }
    }
    std::printf(
        "walk frames %d, fly frames %d; on the raft %d frames, x %.2f .. %.2f; crouched %d frames; "
        "farthest z %.3f; "
        "highest near the wall %.3f\n",
        walkFrames, flyFrames, raftFrames, raftMinX, raftMaxX, crouchFrames, farthestZ,
        highestNearWall);
    EXPECT(walkFrames > 200, "only %d walk frames", walkFrames);
    EXPECT(flyFrames > 0, "never flew again");
    EXPECT(highestOnTerrace >= 5.0, "never climbed onto the terrace (one voxel up)");
    EXPECT(farthestZ <= 44.0, "passed the two-voxel wall at z = 44 (max z %.4f)", farthestZ);
    EXPECT(farthestZ > 43.9, "never reached the wall (max z %.4f)", farthestZ);
    EXPECT(raftFrames > 30 && raftMaxX - raftMinX > 20.0,
           "did not ride the raft far: %d frames, %.2f voxels", raftFrames, raftMaxX - raftMinX);
    EXPECT(highestNearWall > 6.0 && highestNearWall < 6.3,
           "the jump at the wall rose to %.3f, expected 5 + 1.25", highestNearWall);
    EXPECT(crouchFrames > 5 && crouchLower, "crouching: %d frames, box 1.5 high: %d", crouchFrames,
           int(crouchLower));
    if (failures == 0) std::printf("walk check passed\n");
    return failures == 0 ? 0 : 1;
}
