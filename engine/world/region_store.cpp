#include "world/region_store.h"

#include <sqlite3.h>
#include <sstream>

namespace engine::world {

namespace fs = std::filesystem;

namespace {

constexpr int kApplicationId = 0x564F5852;  // "VOXR" in the SQLite header: a voxengine store
constexpr int kFormatVersion = 1;           // PRAGMA user_version

// One prepared statement; finalised on scope exit.
class Statement {
public:
    Statement(sqlite3* db, const char* sql) {
        mRc = sqlite3_prepare_v2(db, sql, -1, &mStmt, nullptr);
    }
    ~Statement() { sqlite3_finalize(mStmt); }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    bool ok() const { return mRc == SQLITE_OK; }
    sqlite3_stmt* get() const { return mStmt; }
    // SQLITE_ROW, SQLITE_DONE or an error code.
    int step() { return sqlite3_step(mStmt); }
    void reset() {
        sqlite3_reset(mStmt);
        sqlite3_clear_bindings(mStmt);
    }
    void bindKey(RegionKey k) {
        sqlite3_bind_int(mStmt, 1, k.x);
        sqlite3_bind_int(mStmt, 2, k.y);
        sqlite3_bind_int(mStmt, 3, k.z);
    }
    std::int64_t integer(int column) const { return sqlite3_column_int64(mStmt, column); }
    std::string text(int column) const {
        const auto* p = sqlite3_column_text(mStmt, column);
        return p ? std::string(reinterpret_cast<const char*>(p),
                               std::size_t(sqlite3_column_bytes(mStmt, column)))
                 : std::string();
    }
    std::span<const std::uint8_t> blob(int column) const {
        const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(mStmt, column));
        return {p, std::size_t(sqlite3_column_bytes(mStmt, column))};
    }

private:
    sqlite3_stmt* mStmt = nullptr;
    int mRc = SQLITE_ERROR;
};

int exec(sqlite3* db, const char* sql) { return sqlite3_exec(db, sql, nullptr, nullptr, nullptr); }

// A single integer from a query (a pragma), or nullopt on error.
std::optional<std::int64_t> queryInt(sqlite3* db, const char* sql) {
    Statement s(db, sql);
    if (!s.ok() || s.step() != SQLITE_ROW) return std::nullopt;
    return s.integer(0);
}

constexpr const char* kSchema = R"(
CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE scene(key TEXT PRIMARY KEY, toml TEXT NOT NULL);
CREATE TABLE regions(x INTEGER NOT NULL, y INTEGER NOT NULL, z INTEGER NOT NULL,
                     raw_bytes INTEGER NOT NULL, data BLOB NOT NULL,
                     PRIMARY KEY (x, y, z)) WITHOUT ROWID;
)";

std::string sizeText(glm::ivec3 s) { return fmt::format("{} {} {}", s.x, s.y, s.z); }

}  // namespace

RegionStore::RegionStore(RegionStore&& other) noexcept
    : mDb(other.mDb),
      mPath(std::move(other.mPath)),
      mInfo(other.mInfo),
      mInTransaction(other.mInTransaction) {
    other.mDb = nullptr;
}

RegionStore& RegionStore::operator=(RegionStore&& other) noexcept {
    if (this != &other) {
        if (mDb) sqlite3_close(mDb);
        mDb = other.mDb;
        mPath = std::move(other.mPath);
        mInfo = other.mInfo;
        mInTransaction = other.mInTransaction;
        other.mDb = nullptr;
    }
    return *this;
}

RegionStore::~RegionStore() {
    if (mDb && mInTransaction) exec(mDb, "ROLLBACK");
    if (mDb) sqlite3_close(mDb);
}

Error RegionStore::fail(const char* what) const {
    return makeError("{}: {}: {}", mPath.string(), what, mDb ? sqlite3_errmsg(mDb) : "no database");
}

static Result<sqlite3*> openDatabase(const fs::path& path, int flags);

bool RegionStore::isStore(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) < 100) return false;
    // The application id may still sit in the write-ahead log: ask SQLite, not the header bytes.
    auto db = openDatabase(path, SQLITE_OPEN_READONLY);
    if (!db) return false;
    const auto id = queryInt(*db, "PRAGMA application_id");
    sqlite3_close(*db);
    return id && *id == kApplicationId;
}

static Result<sqlite3*> openDatabase(const fs::path& path, int flags) {
    sqlite3* db = nullptr;
    const int rc = sqlite3_open_v2(path.c_str(), &db, flags | SQLITE_OPEN_NOMUTEX, nullptr);
    if (rc != SQLITE_OK) {
        Error e = makeError("{}: cannot open the world store: {}", path.string(),
                            db ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
        sqlite3_close(db);
        return e;
    }
    sqlite3_extended_result_codes(db, 1);
    sqlite3_busy_timeout(db, 5000);  // another process committing: wait, then say so
    return db;
}

Result<RegionStore> RegionStore::open(const fs::path& path, bool writable) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return makeError("{}: no such world store", path.string());
    auto db = openDatabase(path, writable ? SQLITE_OPEN_READWRITE : SQLITE_OPEN_READONLY);
    if (!db) return db.error();
    RegionStore store;
    store.mDb = *db;
    store.mPath = path;
    const auto id = queryInt(store.mDb, "PRAGMA application_id");
    if (!id) return store.fail("not a world store");
    if (*id != kApplicationId)
        return makeError("{}: not a world store (SQLite application id {:#x})", path.string(),
                         std::uint32_t(*id));
    // A file cut short reads as zeros past its end: with no log to hold the missing pages, its
    // length must be what the header says.
    const auto walBytes = fs::file_size(path.string() + "-wal", ec);
    if (ec || walBytes == 0) {
        const auto pages = queryInt(store.mDb, "PRAGMA page_count");
        const auto pageSize = queryInt(store.mDb, "PRAGMA page_size");
        const auto bytes = fs::file_size(path, ec);
        if (!pages || !pageSize || ec || std::uint64_t(*pages * *pageSize) != bytes)
            return makeError("{}: damaged world store: {} bytes, its header says {} (cut short?)",
                             path.string(), bytes, pages && pageSize ? *pages * *pageSize : 0);
    }
    if (writable && (exec(store.mDb, "PRAGMA journal_mode=WAL") != SQLITE_OK ||
                     exec(store.mDb, "PRAGMA synchronous=FULL") != SQLITE_OK))
        return store.fail("cannot open for writing");
    if (Status s = store.readMeta(); !s) return s.error();
    return store;
}

Result<RegionStore> RegionStore::openOrCreate(const fs::path& path, glm::ivec3 worldSizeInVoxels,
                                              int regionCells) {
    auto db = openDatabase(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    if (!db) return db.error();
    RegionStore store;
    store.mDb = *db;
    store.mPath = path;
    const auto id = queryInt(store.mDb, "PRAGMA application_id");
    const auto tables = queryInt(store.mDb, "SELECT count(*) FROM sqlite_master");
    if (!id || !tables) return store.fail("not a world store");
    // WAL: readers never block the writer, and a commit appends to the log instead of
    // rewriting pages in place. synchronous=FULL: a commit is on disk when commit() returns.
    if (exec(store.mDb, "PRAGMA journal_mode=WAL") != SQLITE_OK ||
        exec(store.mDb, "PRAGMA synchronous=FULL") != SQLITE_OK)
        return store.fail("cannot open for writing");
    if (*id == 0 && *tables == 0) {
        // A new (or empty) file: the schema, the meta rows and the application id are one
        // transaction, so a crash here leaves an empty file that the next attempt makes again.
        const std::string sql = fmt::format(
            "BEGIN IMMEDIATE; {} PRAGMA application_id={}; PRAGMA user_version={}; "
            "INSERT INTO meta VALUES('format', '{}'), ('world_size', '{}'), "
            "('region_cells', '{}'), ('commits', '0'); COMMIT;",
            kSchema, kApplicationId, kFormatVersion, kFormatVersion, sizeText(worldSizeInVoxels),
            regionCells);
        if (exec(store.mDb, sql.c_str()) != SQLITE_OK) {
            Status s = store.fail("cannot make the world store");
            exec(store.mDb, "ROLLBACK");
            return s.error();
        }
    } else if (*id != kApplicationId) {
        return makeError(
            "{}: not a world store (SQLite application id {:#x}); refusing to "
            "overwrite it",
            path.string(), std::uint32_t(*id));
    }
    if (Status s = store.readMeta(); !s) return s.error();
    return store;
}

Status RegionStore::readMeta() {
    const auto version = queryInt(mDb, "PRAGMA user_version");
    if (!version) return fail("cannot read the store's header");
    if (*version != kFormatVersion)
        return makeError("{}: world store format {}, this build reads {}", mPath.string(), *version,
                         kFormatVersion);
    Statement s(mDb, "SELECT key, value FROM meta");
    if (!s.ok()) return fail("cannot read the store's meta table");
    std::map<std::string, std::string> meta;
    int rc;
    while ((rc = s.step()) == SQLITE_ROW) meta[s.text(0)] = s.text(1);
    if (rc != SQLITE_DONE) return fail("cannot read the store's meta table");
    auto bad = [&](const char* key) {
        return makeError("{}: damaged world store: meta '{}' = '{}'", mPath.string(), key,
                         meta.count(key) ? meta[key] : "(missing)");
    };
    {
        std::istringstream in(meta["world_size"]);
        glm::ivec3 size;
        if (!(in >> size.x >> size.y >> size.z) || glm::any(glm::lessThan(size, glm::ivec3(1))) ||
            glm::any(glm::greaterThan(size, glm::ivec3(1 << 15))))
            return bad("world_size");
        mInfo.worldSizeInVoxels = size;
    }
    {
        std::istringstream in(meta["region_cells"]);
        int cells = 0;
        if (!(in >> cells) || cells < 1 || cells > 256) return bad("region_cells");
        mInfo.regionCells = cells;
    }
    std::istringstream in(meta["commits"]);
    if (!(in >> mInfo.commits)) return bad("commits");
    return {};
}

Result<std::optional<std::vector<std::uint8_t>>> RegionStore::readRegion(RegionKey key) const {
    Statement s(mDb, "SELECT data FROM regions WHERE x = ?1 AND y = ?2 AND z = ?3");
    if (!s.ok()) return fail("cannot read a region");
    s.bindKey(key);
    const int rc = s.step();
    if (rc == SQLITE_DONE) return std::optional<std::vector<std::uint8_t>>();
    if (rc != SQLITE_ROW) return fail("cannot read a region");
    const auto blob = s.blob(0);
    return std::optional<std::vector<std::uint8_t>>(
        std::vector<std::uint8_t>(blob.begin(), blob.end()));
}

Status RegionStore::forEachRegion(
    const std::function<Status(RegionKey, std::span<const std::uint8_t>)>& visit) const {
    Statement s(mDb, "SELECT x, y, z, data FROM regions ORDER BY z, y, x");
    if (!s.ok()) return fail("cannot read the regions");
    int rc;
    while ((rc = s.step()) == SQLITE_ROW) {
        const RegionKey key{int(s.integer(0)), int(s.integer(1)), int(s.integer(2))};
        if (Status st = visit(key, s.blob(3)); !st) return st;
    }
    if (rc != SQLITE_DONE) return fail("cannot read the regions");
    return {};
}

Result<std::vector<RegionRow>> RegionStore::listRegions() const {
    Statement s(mDb, "SELECT x, y, z, raw_bytes, length(data) FROM regions ORDER BY z, y, x");
    if (!s.ok()) return fail("cannot list the regions");
    std::vector<RegionRow> rows;
    int rc;
    while ((rc = s.step()) == SQLITE_ROW)
        rows.push_back({{int(s.integer(0)), int(s.integer(1)), int(s.integer(2))},
                        std::uint64_t(s.integer(3)),
                        std::uint64_t(s.integer(4))});
    if (rc != SQLITE_DONE) return fail("cannot list the regions");
    return rows;
}

Result<std::map<std::string, std::string>> RegionStore::sceneKeys() const {
    Statement s(mDb, "SELECT key, toml FROM scene");
    if (!s.ok()) return fail("cannot read the scene keys");
    std::map<std::string, std::string> keys;
    int rc;
    while ((rc = s.step()) == SQLITE_ROW) keys[s.text(0)] = s.text(1);
    if (rc != SQLITE_DONE) return fail("cannot read the scene keys");
    return keys;
}

Status RegionStore::failTransaction(const char* what) {
    Error e = makeError("{}: {}; the store keeps its previous state: {}", mPath.string(), what,
                        sqlite3_errmsg(mDb));
    if (mInTransaction) exec(mDb, "ROLLBACK");
    mInTransaction = false;
    mPendingRegionCells = 0;
    return e;
}

Status RegionStore::begin(bool replaceAll, int regionCells) {
    if (exec(mDb, "BEGIN IMMEDIATE") != SQLITE_OK) return failTransaction("cannot start the save");
    mInTransaction = true;
    // A connection kept open across saves (vox play's saver) sees other writers' commits here:
    // the counter this transaction increments is the one on disk now.
    if (Status s = readMeta(); !s) {
        exec(mDb, "ROLLBACK");
        mInTransaction = false;
        return s;
    }
    if (!replaceAll) return {};
    const std::string sql = fmt::format(
        "DELETE FROM regions; DELETE FROM scene; "
        "UPDATE meta SET value = '{}' WHERE key = 'region_cells';",
        regionCells);
    if (exec(mDb, sql.c_str()) != SQLITE_OK) return failTransaction("cannot save");
    mPendingRegionCells = regionCells;
    return {};
}

Status RegionStore::put(const EncodedRegion& r) {
    Statement put(mDb, "INSERT OR REPLACE INTO regions VALUES(?1, ?2, ?3, ?4, ?5)");
    if (!put.ok()) return failTransaction("cannot save a region");
    put.bindKey(r.key);
    sqlite3_bind_int64(put.get(), 4, std::int64_t(r.rawBytes));
    sqlite3_bind_blob64(put.get(), 5, r.blob.data(), r.blob.size(), SQLITE_STATIC);
    if (put.step() != SQLITE_DONE) return failTransaction("cannot save a region");
    return {};
}

Status RegionStore::erase(RegionKey key) {
    Statement erase(mDb, "DELETE FROM regions WHERE x = ?1 AND y = ?2 AND z = ?3");
    if (!erase.ok()) return failTransaction("cannot save a region");
    erase.bindKey(key);
    if (erase.step() != SQLITE_DONE) return failTransaction("cannot save a region");
    return {};
}

Status RegionStore::putSceneKey(const std::string& name, const std::string& toml) {
    Statement key(mDb, "INSERT OR REPLACE INTO scene VALUES(?1, ?2)");
    if (!key.ok()) return failTransaction("cannot save the scene keys");
    sqlite3_bind_text(key.get(), 1, name.data(), int(name.size()), SQLITE_STATIC);
    sqlite3_bind_text64(key.get(), 2, toml.data(), toml.size(), SQLITE_STATIC, SQLITE_UTF8);
    if (key.step() != SQLITE_DONE) return failTransaction("cannot save the scene keys");
    return {};
}

Status RegionStore::commitTransaction(std::optional<glm::ivec3> worldSizeInVoxels) {
    const std::uint64_t commits = mInfo.commits + 1;
    const glm::ivec3 size = worldSizeInVoxels.value_or(mInfo.worldSizeInVoxels);
    const std::string meta = fmt::format(
        "UPDATE meta SET value = '{}' WHERE key = 'commits'; "
        "UPDATE meta SET value = '{}' WHERE key = 'world_size';",
        commits, sizeText(size));
    if (exec(mDb, meta.c_str()) != SQLITE_OK) return failTransaction("cannot save");
    if (exec(mDb, "COMMIT") != SQLITE_OK) return failTransaction("cannot commit the save");
    mInTransaction = false;
    mInfo.commits = commits;
    if (mPendingRegionCells) mInfo.regionCells = mPendingRegionCells;
    mPendingRegionCells = 0;
    mInfo.worldSizeInVoxels = size;
    return {};
}

Status RegionStore::commit(const StoreCommit& change) {
    if (Status s = begin(change.replaceAll); !s) return s;
    if (change.expectedCommits && mInfo.commits != *change.expectedCommits) {
        exec(mDb, "ROLLBACK");
        mInTransaction = false;
        return makeError(
            "{}: changed by another writer since this world was loaded or saved; not saved (the "
            "next save writes the whole world)",
            mPath.string());
    }
    for (const EncodedRegion& r : change.put)
        if (Status s = put(r); !s) return s;
    for (const RegionKey& k : change.erase)
        if (Status s = erase(k); !s) return s;
    for (const auto& [name, toml] : change.sceneKeys)
        if (Status s = putSceneKey(name, toml); !s) return s;
    return commitTransaction(change.worldSizeInVoxels);
}

Result<std::uint64_t> RegionStore::regionRows() const {
    Statement s(mDb, "SELECT count(*) FROM regions");
    if (!s.ok() || s.step() != SQLITE_ROW) return fail("cannot count the regions");
    return std::uint64_t(s.integer(0));
}

Result<std::string> RegionStore::integrityCheck() const {
    Statement s(mDb, "PRAGMA integrity_check");
    if (!s.ok() || s.step() != SQLITE_ROW) return fail("integrity check failed");
    const std::string first = s.text(0);
    return first == "ok" ? std::string() : first;
}

void RegionStore::abandon() {
    if (mDb) sqlite3_db_config(mDb, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
}

std::uint64_t RegionStore::fileBytes() const {
    std::error_code ec;
    std::uint64_t total = 0;
    for (const fs::path& p : {mPath, fs::path(mPath.string() + "-wal")}) {
        const auto n = fs::file_size(p, ec);
        if (!ec) total += n;
    }
    return total;
}

}  // namespace engine::world
