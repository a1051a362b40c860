// A world on disk as two files: a scene file (text: palette, cameras, sky, ...) and its voxels in
// an OpenVDB payload beside it that the scene file names. Written atomic as a pair: the payload
// goes to a new name `STEM.N.vdb` (N above that of any such file in the folder), then the scene
// file naming it is written and renamed into place, and that rename is the commit. A failure at
// any step leaves the previous scene file naming the previous payload, both unchanged; the new
// payload is removed. Used by the sandbox's saves and by `vox import`.
//
// Only files the world's own writes created are ever removed. A write lists what it is about to
// create in a journal beside the scene file (`.NAME.writing`) before creating it, so even a write
// killed half-way leaves nothing unlisted; after the commit, the world's files the new scene file
// does not name are removed and the rest make up its manifest (`.NAME.payloads`). Other files
// named like payloads (a VDB sequence `smoke.0001.vdb` beside `smoke.toml`) are never touched.
//
// Writers of one world (an import, a save, an autosave, two `vox play` with one --save) exclude
// each other: each holds a record lock on the world for its write (core/folder_lock.h, one byte
// of FOLDER/.lock picked by the scene file's name), and a second is refused, naming the first's
// process.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "world/scene.h"

namespace engine::scene {

// A further payload the scene file names (a save's object models).
struct PayloadFile {
    std::string fileName;  // in the scene file's folder
    // Writes the file; not called if it exists already (such names say what is inside).
    std::function<Status(const std::filesystem::path&)> write;
};

struct WorldPairOptions {
    // Never removed, and no longer listed as the world's own (an import's input: it may be an
    // earlier payload of the same world).
    std::vector<std::filesystem::path> keep;
    std::vector<PayloadFile> extraPayloads;
    // Fault injection for tests: runs after the payloads and the scene file's text are written,
    // before the rename that commits the pair; an error aborts the save.
    std::function<Status()> beforeCommit;
};

// `sceneText(payloadFileName)` gives the scene file's text for the payload's file name.
Status writeWorldPair(
    const world::Scene& scene, const std::filesystem::path& sceneFile,
    const std::function<std::string(const std::string& payloadFileName)>& sceneText,
    const WorldPairOptions& options = {});

// What payload names begin with: the scene file's stem, shortened if needed so that
// `STEM.object-HASH.vdb` and `STEM.N.vdb` fit in a folder entry.
std::string payloadStem(const std::filesystem::path& sceneFile);
// The lists of the world's own payloads: the manifest (`.NAME.payloads`), and the journal of a
// write in progress (`.NAME.writing`: what it is about to create; left behind if it dies).
std::filesystem::path payloadManifest(const std::filesystem::path& sceneFile);
std::filesystem::path payloadJournal(const std::filesystem::path& sceneFile);

// The header comments (first line) of scene files the engine wrote. A save replaces only a save,
// an import a save or an import; a hand-written scene file is never replaced.
inline constexpr std::string_view kSaveMarker = "Saved by vox play";
inline constexpr std::string_view kImportMarker = "Imported by `vox import`";
// True if the file's first line is `# ` followed by `marker` (and maybe more).
bool sceneFileMarked(const std::filesystem::path& sceneFile, std::string_view marker);

}  // namespace engine::scene
