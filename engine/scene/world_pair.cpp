#include "scene/world_pair.h"

#include <algorithm>
#include <cstdint>
#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <set>

#include "core/atomic_file.h"
#include "core/file_name.h"
#include "core/folder_lock.h"
#include "core/hash.h"
#include "io/vdb_export.h"

namespace engine::scene {

namespace fs = std::filesystem;

namespace {

// The longest suffix a payload name adds to its stem: ".object-" + 16 hex digits + ".vdb".
constexpr std::size_t kPayloadSuffixRoom = 28;

fs::path folderOf(const fs::path& sceneFile) {
    return sceneFile.parent_path().empty() ? fs::path(".") : sceneFile.parent_path();
}

// N of `STEM.N.vdb`, if `name` is one.
std::optional<std::uint64_t> generationOf(const std::string& name, const std::string& stem) {
    if (name.size() <= stem.size() + 1 || name.compare(0, stem.size() + 1, stem + ".") != 0)
        return std::nullopt;
    const std::string rest = name.substr(stem.size() + 1);
    const auto dot = rest.find('.');
    if (dot == std::string::npos || dot == 0 || dot > 18 || rest.substr(dot) != ".vdb")
        return std::nullopt;
    const std::string digits = rest.substr(0, dot);
    if (digits.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return std::stoull(digits);
}

// The new payload's generation: above every `STEM.N.vdb` in the folder, so it never replaces a
// file that is there (ours or not).
std::uint64_t nextGeneration(const fs::path& dir, const std::string& stem) {
    std::uint64_t next = 1;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
        if (auto n = generationOf(e.path().filename().string(), stem))
            next = std::max(next, *n + 1);
    return next;
}

// The names in a list of the world's own payloads (the manifest or the journal); only plain
// names of this world's payloads are taken, so a damaged or edited list cannot point elsewhere.
std::set<std::string> readList(const fs::path& list, const std::string& stem) {
    std::set<std::string> names;
    std::ifstream in(list);
    std::string line;
    while (std::getline(in, line)) {
        const bool ours =
            line.size() > stem.size() + 5 && line.compare(0, stem.size() + 1, stem + ".") == 0 &&
            line.compare(line.size() - 4, 4, ".vdb") == 0 && line.find('/') == std::string::npos;
        if (ours) names.insert(line);
    }
    return names;
}

Status writeList(const fs::path& list, const fs::path& sceneFile,
                 const std::set<std::string>& names) {
    std::string text =
        fmt::format("# Payloads vox wrote for {}; removed once it names them no more\n",
                    sceneFile.filename().string());
    for (const std::string& n : names) text += n + "\n";
    return writeFileAtomically(list, text);
}

fs::path beside(const fs::path& sceneFile, const std::string& suffix) {
    std::string name = ".";
    name += fitFileName(sceneFile.filename().string() + suffix, kMaxFileName - 1);
    return sceneFile.parent_path() / name;
}

// The world's lock: FOLDER/.lock's bytes from 2^62 up are worlds', one per scene file name
// (captures claim their frame numbers, far below).
Result<FolderLock> lockWorld(const fs::path& sceneFile) {
    const std::uint64_t byte =
        (std::uint64_t(1) << 62) | (fnv1a64(sceneFile.filename().string()) >> 2);
    return FolderLock::acquire(folderOf(sceneFile), "save or import", byte, 1, sceneFile.string());
}

}  // namespace

std::string payloadStem(const fs::path& sceneFile) {
    return fitFileName(sceneFile.stem().string(), kMaxFileName - kPayloadSuffixRoom);
}

fs::path payloadManifest(const fs::path& sceneFile) { return beside(sceneFile, ".payloads"); }

fs::path payloadJournal(const fs::path& sceneFile) { return beside(sceneFile, ".writing"); }

bool sceneFileMarked(const fs::path& sceneFile, std::string_view marker) {
    std::ifstream in(sceneFile);
    std::string first;
    std::getline(in, first);
    return first.size() >= marker.size() + 2 && first.compare(0, 2, "# ") == 0 &&
           first.compare(2, marker.size(), marker) == 0;
}

Status writeWorldPair(
    const world::Scene& scene, const fs::path& sceneFile,
    const std::function<std::string(const std::string& payloadFileName)>& sceneText,
    const WorldPairOptions& options) {
    // The scene file's temporary first: a scene path that is a folder (or in no folder) is
    // refused before any payload is written.
    AtomicFile sceneOut;
    if (Status s = sceneOut.open(sceneFile); !s) return s;
    auto lock = lockWorld(sceneFile);
    if (!lock) return lock.error();

    const fs::path dir = sceneFile.parent_path();
    removeStaleTemporaries(
        folderOf(sceneFile));  // left by saves killed mid-write (every save, not once per process)
    const std::string stem = payloadStem(sceneFile);
    const fs::path manifest = payloadManifest(sceneFile), journal = payloadJournal(sceneFile);
    std::error_code ec;
    const bool died =
        fs::exists(journal, ec);  // a write that died left it: its files are the world's too
    const std::set<std::string> listed = readList(manifest, stem),
                                unfinished = readList(journal, stem);
    const std::string payloadName =
        fmt::format("{}.{}.vdb", stem, nextGeneration(folderOf(sceneFile), stem));

    // What this write creates goes in the journal before it is written: the payload and the
    // further payloads not there yet.
    std::set<std::string> named{payloadName}, created{payloadName};
    std::vector<const PayloadFile*> toWrite;
    for (const PayloadFile& p : options.extraPayloads) {
        named.insert(p.fileName);
        if (fs::exists(dir / p.fileName, ec)) continue;
        toWrite.push_back(&p);
        created.insert(p.fileName);
    }
    std::set<std::string> journalled = unfinished;
    journalled.insert(created.begin(), created.end());
    if (Status s = writeList(journal, sceneFile, journalled); !s) return s;

    std::vector<fs::path> written;
    auto undo = [&](const Status& failed) {
        sceneOut.abandon();
        for (const fs::path& w : written)
            fs::remove(w, ec);               // the old scene file names none of them
        if (!died) fs::remove(journal, ec);  // (a dead write's journal stays for the next)
        return failed;
    };
    for (const PayloadFile* p : toWrite) {
        if (Status s = p->write(dir / p->fileName); !s) return undo(s);
        written.push_back(dir / p->fileName);
    }
    // Colour grids included so other OpenVDB tools show the world in colour (loading needs only
    // the ids).
    if (Status s = io::exportVdb(scene, dir / payloadName); !s) return undo(s);
    written.push_back(dir / payloadName);

    Status s = sceneOut.write(sceneText(payloadName));
    if (s && options.beforeCommit) s = options.beforeCommit();
    if (s) s = sceneOut.commit();
    if (!s) return undo(s);

    // Committed. The world's own files the new scene file does not name go; the kept ones are the
    // user's from now on.
    std::set<std::string> own, all = listed;
    all.insert(journalled.begin(), journalled.end());
    for (const std::string& name : all) {
        const fs::path file = dir / name;
        const bool kept =
            std::any_of(options.keep.begin(), options.keep.end(),
                        [&](const fs::path& k) { return fs::equivalent(k, file, ec); });
        if (named.count(name))
            own.insert(name);
        else if (!kept)
            fs::remove(file, ec);
    }
    // If the manifest cannot be written, the journal stays and the next write tidies up.
    if (writeList(manifest, sceneFile, own)) fs::remove(journal, ec);
    return {};
}

}  // namespace engine::scene
