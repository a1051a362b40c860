#include "job_manifest.h"

#include <ctime>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/check.h"
#include "core/checksum.h"
#include "core/exclusive_file_lock.h"
#include "subprocess.h"

namespace vox::job {

namespace fs = std::filesystem;

namespace {

// What every reader relies on, checked once when the file is read: a hand-edited or foreign file
// is refused with its name instead of surprising the code that walks it.
engine::Status checkShape(const engine::Json& m, const fs::path& file) {
    if (m.get("format").string() != kManifestFormat)
        return engine::makeError("{}: not a vox job manifest (format '{}', expected '{}')",
                                 file.string(), m.get("format").string(), kManifestFormat);
    const auto& tasks = m.get("tasks").items();
    if (tasks.empty()) return engine::makeError("{}: no tasks", file.string());
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const engine::Json& t = tasks[i];
        if (t.get("index").number(-1) != double(i) || !t.get("first").isNumber() ||
            !t.get("last").isNumber() || t.get("last").number() < t.get("first").number())
            return engine::makeError("{}: task {} is malformed (index, first, last)", file.string(),
                                     i);
    }
    for (const char* key : {"kind", "settings_hash", "engine"})
        if (!m.get(key).isString())
            return engine::makeError("{}: '{}' is missing", file.string(), key);
    return {};
}

engine::Result<engine::Json> readManifestFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return engine::makeError("{}: no job here (no job manifest)", file.string());
    std::stringstream text;
    text << in.rdbuf();
    auto m = engine::parseJson(text.str(), file.string());
    if (!m) return m.error();
    if (engine::Status s = checkShape(*m, file); !s) return s.error();
    return m;
}

}  // namespace

fs::path manifestPath(const fs::path& dir) { return dir / "job.json"; }
fs::path jobFolder(const fs::path& dir) { return dir / "job"; }

engine::Result<engine::Json> readManifest(const fs::path& dir) {
    return readManifestFile(manifestPath(dir));
}

engine::Status updateManifest(const fs::path& dir,
                              const std::function<engine::Status(engine::Json&)>& change) {
    std::error_code ec;
    fs::create_directories(jobFolder(dir), ec);
    if (ec)
        return engine::makeError("{}: cannot create folder: {}", jobFolder(dir).string(),
                                 ec.message());
    auto lock = engine::ExclusiveFileLock::acquire(jobFolder(dir) / "job.lock");
    if (!lock) return lock.error();
    engine::Json manifest;
    if (fs::exists(manifestPath(dir), ec)) {
        auto m = readManifestFile(manifestPath(dir));
        if (!m) return m.error();
        manifest = std::move(*m);
    }
    if (engine::Status s = change(manifest); !s) return s;
    return engine::writeFileAtomically(manifestPath(dir), manifest.dump());
}

std::vector<TaskRange> splitUnits(std::uint32_t first, std::uint32_t last, std::uint32_t tasks) {
    const std::uint64_t count = std::uint64_t(last) - first + 1;
    tasks = std::uint32_t(std::min<std::uint64_t>(std::max(tasks, 1u), count));
    std::vector<TaskRange> out;
    for (std::uint32_t i = 0; i < tasks; ++i) {
        const std::uint64_t a = count * i / tasks, b = count * (i + 1) / tasks;
        out.push_back({i, first + std::uint32_t(a), first + std::uint32_t(b - 1)});
    }
    return out;
}

engine::Json& taskRecord(engine::Json& manifest, std::uint32_t index) {
    auto& tasks = manifest["tasks"].items();
    CHECK(index < tasks.size());
    return tasks[index];
}

const engine::Json& taskRecord(const engine::Json& manifest, std::uint32_t index) {
    const auto& tasks = manifest.get("tasks").items();
    CHECK(index < tasks.size());
    return tasks[index];
}

TaskRange taskRange(const engine::Json& task) {
    return {std::uint32_t(task.get("index").number()), std::uint32_t(task.get("first").number()),
            std::uint32_t(task.get("last").number())};
}

const engine::Json& unitRecord(const engine::Json& manifest, const std::string& units,
                               std::uint32_t unit) {
    static const engine::Json kNone;
    const std::uint32_t first = std::uint32_t(manifest.get("first").number());
    const auto& records = manifest.get(units).items();
    if (unit < first || unit - first >= records.size()) return kNone;
    return records[unit - first];
}

void setUnitRecord(engine::Json& manifest, const std::string& units, std::uint32_t unit,
                   engine::Json record) {
    const std::uint32_t first = std::uint32_t(manifest.get("first").number());
    CHECK(unit >= first);
    auto& records = manifest[units].items();
    if (records.size() <= unit - first) records.resize(unit - first + 1);
    records[unit - first] = std::move(record);
}

std::string hostName() {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return "unknown";
    return name;
}

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

const std::string& engineVersion() {
    static const std::string version = [] {
        auto sum = engine::fileChecksum(thisExecutable());
        return fmt::format("vox {} (build {})", VOX_VERSION, sum ? *sum : std::string("unknown"));
    }();
    return version;
}

}  // namespace vox::job
