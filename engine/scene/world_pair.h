// A world on disk as two files: a scene file (text: palette, cameras, sky, ...) and its voxels in
// an OpenVDB payload beside it that the scene file names. Written atomic as a pair: the payload
// goes to a new name `STEM.N.vdb` (N one more than any before), then the scene file naming it is
// written and renamed into place, and that rename is the commit. A failure at any step leaves
// the previous scene file naming the previous payload, both unchanged; the new payload is
// removed. Older payload generations go after the commit. Used by the sandbox's saves and by
// `vox import`.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "world/scene.h"

namespace engine::scene {

struct WorldPairOptions {
    // Payload generations of the same stem (STEM.N.vdb) other than the new one are removed after
    // the commit, except these (an import's own input, say).
    std::vector<std::filesystem::path> keep;
    // Fault injection for tests: runs after the payload and the scene file's text are written,
    // before the rename that commits the pair; an error aborts the save.
    std::function<Status()> beforeCommit;
};

// `sceneText(payloadFileName)` gives the scene file's text for the payload's file name.
Status writeWorldPair(const world::Scene& scene, const std::filesystem::path& sceneFile,
                      const std::function<std::string(const std::string& payloadFileName)>& sceneText,
                      const WorldPairOptions& options = {});

}  // namespace engine::scene
