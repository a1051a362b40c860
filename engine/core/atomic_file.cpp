#include "core/atomic_file.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <set>
#include <signal.h>
#include <streambuf>
#include <string>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

#include "core/file_name.h"

namespace engine {

namespace fs = std::filesystem;

namespace {

// ---- failure injection (tests) ----
std::mutex gInjectMutex;
std::optional<std::uint64_t> gOperationsLeft;
bool gEnvironmentRead = false;

// True if this write/fsync must fail as on a full disk.
bool injectedFailure() {
    std::lock_guard lock(gInjectMutex);
    if (!gEnvironmentRead) {
        gEnvironmentRead = true;
        if (const char* v = std::getenv("VOX_FAIL_WRITES");
            v && std::strncmp(v, "after:", 6) == 0) {
            char* end = nullptr;
            unsigned long long n = std::strtoull(v + 6, &end, 10);
            if (end != v + 6 && *end == '\0') gOperationsLeft = n;
        }
    }
    if (!gOperationsLeft) return false;
    if (*gOperationsLeft == 0) return true;
    --*gOperationsLeft;
    return false;
}

// ---- stale temporaries ----
constexpr std::string_view kTempMarker = ".tmp-";

// The process id in a temporary's name, or 0: `.NAME.tmp-PID`, or the older `NAME.tmp-PID` when
// NAME ends in an extension the engine writes (so a user's "notes.tmp-2023" is not taken).
pid_t temporaryOwner(const std::string& name) {
    auto at = name.rfind(kTempMarker);
    if (at == std::string::npos || at == 0) return 0;
    std::string digits = name.substr(at + kTempMarker.size());
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
        return 0;
    if (name.front() != '.') {
        const std::string ext = fs::path(name.substr(0, at)).extension().string();
        constexpr std::array<std::string_view, 8> kOurs = {".png", ".exr",  ".vdb", ".toml",
                                                           ".csv", ".json", ".md",  ".mp4"};
        if (std::find(kOurs.begin(), kOurs.end(), ext) == kOurs.end()) return 0;
    }
    return pid_t(std::stol(digits));
}

// The temporaries this process has open: the only files at a `.NAME.tmp-PID` of ours that are not
// leftovers (of a process that had our pid before) or planted by someone else.
std::mutex gOpenMutex;
std::set<fs::path> gOpenTemporaries;

// Creates the temporary exclusively, never following a symlink at its name: whatever is there is
// not ours (see gOpenTemporaries) and is unlinked, not written through.
int createTemporary(const fs::path& temporary) {
    {
        std::lock_guard lock(gOpenMutex);
        if (!gOpenTemporaries.insert(temporary).second) {
            errno = EBUSY;  // this process writes the same file twice at once
            return -1;
        }
    }
    constexpr int kFlags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
    int fd = ::open(temporary.c_str(), kFlags, 0666);
    if (fd < 0 && errno == EEXIST && ::unlink(temporary.c_str()) == 0)
        fd = ::open(temporary.c_str(), kFlags, 0666);
    if (fd < 0) {
        const int error = errno;
        std::lock_guard lock(gOpenMutex);
        gOpenTemporaries.erase(temporary);
        errno = error;
    }
    return fd;
}

void forgetTemporary(const fs::path& temporary) {
    std::lock_guard lock(gOpenMutex);
    gOpenTemporaries.erase(temporary);
}

std::mutex gSweptMutex;
std::set<fs::path>
    gSweptFolders;  // each folder once per process: a dead process writes nothing new

void sweepOnce(const fs::path& folder) {
    std::error_code ec;
    fs::path key = fs::weakly_canonical(folder, ec);
    if (ec) key = folder;
    {
        std::lock_guard lock(gSweptMutex);
        if (!gSweptFolders.insert(key).second) return;
    }
    removeStaleTemporaries(folder);
}

}  // namespace

fs::path temporaryPathFor(const fs::path& target) {
    const std::string suffix = std::string(kTempMarker) + std::to_string(::getpid());
    // A long NAME is shortened so that `.NAME.tmp-PID` fits in a folder entry as NAME does.
    std::string name = ".";
    name += fitFileName(target.filename().string(), kMaxFileName - 1 - suffix.size());
    name += suffix;
    return target.parent_path() / name;
}

std::size_t removeStaleTemporaries(const fs::path& folder) {
    std::size_t removed = 0;
    std::error_code ec;
    for (const fs::directory_entry& e :
         fs::directory_iterator(folder.empty() ? fs::path(".") : folder, ec)) {
        pid_t pid = temporaryOwner(e.path().filename().string());
        if (pid <= 0 || pid == ::getpid() || !e.is_regular_file(ec)) continue;
        // ESRCH: no such process. EPERM means alive (another user's), so it is left alone.
        if (::kill(pid, 0) == -1 && errno == ESRCH && fs::remove(e.path(), ec)) ++removed;
    }
    return removed;
}

void failWritesAfter(std::optional<std::uint64_t> operations) {
    std::lock_guard lock(gInjectMutex);
    gEnvironmentRead = true;  // the test's setting wins over the environment
    gOperationsLeft = operations;
}

// The stream's buffer: collects small writes, hands them to AtomicFile::write in 64 KiB blocks.
class AtomicFile::Buffer final : public std::streambuf {
public:
    explicit Buffer(AtomicFile& file) : mFile(file) {
        setp(mData.data(), mData.data() + mData.size());
    }
    // Writes what is buffered; false if the file failed.
    bool drain() {
        const std::size_t n = std::size_t(pptr() - pbase());
        setp(mData.data(), mData.data() + mData.size());
        return n == 0 || mFile.writeDirect(mData.data(), n).ok();
    }
    std::size_t pending() const { return std::size_t(pptr() - pbase()); }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }
    // tellp and seekp (OpenVDB patches its grid offsets after writing a grid).
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
        const off_type here = off_type(mFile.tell());
        if (dir == std::ios_base::cur && off == 0) return pos_type(here);
        off_type target = dir == std::ios_base::beg   ? off
                          : dir == std::ios_base::cur ? here + off
                                                      : -1;
        if (target < 0 || !mFile.seek(std::uint64_t(target)).ok()) return pos_type(off_type(-1));
        return pos_type(target);
    }
    pos_type seekpos(pos_type pos, std::ios_base::openmode which) override {
        return seekoff(off_type(pos), std::ios_base::beg, which);
    }

private:
    AtomicFile& mFile;
    std::array<char, 64 * 1024> mData;
};

AtomicFile::AtomicFile() = default;

AtomicFile::~AtomicFile() { abandon(); }

Status AtomicFile::open(const fs::path& target) {
    abandon();
    mTarget = target;
    mError.reset();
    mPosition = 0;
    std::error_code ec;
    if (fs::is_directory(target, ec))
        return makeError("{} is a folder; give a file name to write", target.string());
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(folder, ec))
        return makeError("{}: cannot write: '{}' is not a folder", target.string(),
                         folder.string());
    if (target.filename().string().size() > kMaxFileName)
        return makeError("{}: cannot create: {}", target.string(), std::strerror(ENAMETOOLONG));
    sweepOnce(folder);
    mTemporary = temporaryPathFor(target);
    mFd = createTemporary(mTemporary);
    if (mFd < 0) {
        const int error = errno;
        mTemporary.clear();
        return makeError("{}: cannot create: {}", target.string(), std::strerror(error));
    }
    // A replaced file keeps its permissions (a private save stays private).
    struct stat previous {};
    if (::stat(target.c_str(), &previous) == 0 && S_ISREG(previous.st_mode))
        (void)::fchmod(mFd, previous.st_mode & 07777);
    return {};
}

void AtomicFile::recordError(std::string_view what, int error) {
    if (!mError)
        mError = makeError("{}: cannot {}: {}", mTarget.string(), what,
                           error ? std::strerror(error) : "unknown error");
}

Status AtomicFile::fail(std::string_view what, int error) {
    recordError(what, error);
    return *mError;
}

Status AtomicFile::writeDirect(const void* data, std::size_t bytes) {
    if (mError) return *mError;
    if (mFd < 0) return fail("write", EBADF);
    const char* p = static_cast<const char*>(data);
    while (bytes > 0) {
        if (injectedFailure()) return fail("write", ENOSPC);
        ssize_t n = ::write(mFd, p, bytes);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return fail("write", errno);
        if (n == 0) return fail("write", ENOSPC);  // no progress: treat as a full disk
        p += n;
        bytes -= std::size_t(n);
        mPosition += std::uint64_t(n);
    }
    return {};
}

Status AtomicFile::write(const void* data, std::size_t bytes) {
    if (mBuffer && !mBuffer->drain()) return *mError;  // keep the stream's bytes in order
    return writeDirect(data, bytes);
}

std::ostream& AtomicFile::stream() {
    if (!mStream) {
        mBuffer = std::make_unique<Buffer>(*this);
        mStream = std::make_unique<std::ostream>(mBuffer.get());
    }
    return *mStream;
}

std::uint64_t AtomicFile::tell() const { return mPosition + (mBuffer ? mBuffer->pending() : 0); }

Status AtomicFile::seek(std::uint64_t position) {
    if (mBuffer && !mBuffer->drain()) return *mError;
    if (mError) return *mError;
    if (::lseek(mFd, off_t(position), SEEK_SET) < 0) return fail("seek", errno);
    mPosition = position;
    return {};
}

Status AtomicFile::commit() {
    if (mFd < 0 && !mError) return makeError("{}: not open for writing", mTarget.string());
    if (mBuffer) mBuffer->drain();
    if (!mError) {
        if (injectedFailure())
            recordError("flush to disk", ENOSPC);
        else if (::fsync(mFd) != 0)
            recordError("flush to disk", errno);
    }
    if (!mError) {
        const int fd = mFd;
        mFd = -1;
        if (::close(fd) != 0)
            recordError("close", errno);  // NFS and quotas report write errors here
    }
    if (!mError && ::rename(mTemporary.c_str(), mTarget.c_str()) != 0)
        recordError("replace the file", errno);
    if (mError) {
        Error error = *mError;
        abandon();
        return error;
    }
    forgetTemporary(mTemporary);
    mTemporary.clear();
    // The rename itself reaches the disk with the folder's fsync; the new file is complete
    // either way, so a failure here is not reported.
    const fs::path folder = mTarget.parent_path().empty() ? fs::path(".") : mTarget.parent_path();
    if (int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return {};
}

void AtomicFile::abandon() {
    if (mFd >= 0) ::close(mFd);
    mFd = -1;
    if (!mTemporary.empty()) {
        ::unlink(mTemporary.c_str());
        forgetTemporary(mTemporary);
    }
    mTemporary.clear();
    mStream.reset();
    mBuffer.reset();
}

Status writeFileAtomically(const fs::path& target, std::string_view bytes) {
    return writeFileAtomically(target, [&](AtomicFile& file) { return file.write(bytes); });
}

Status writeFileAtomically(const fs::path& target,
                           const std::function<Status(AtomicFile& file)>& write) {
    AtomicFile file;
    if (Status s = file.open(target); !s) return s;
    if (Status s = write(file); !s) return s;  // the destructor removes the temporary
    return file.commit();
}

Status replaceFileAtomically(const fs::path& target,
                             const std::function<Status(const fs::path& temporary)>& writeTo) {
    AtomicFile file;
    if (Status s = file.open(target); !s) return s;
    if (Status s = writeTo(file.temporary()); !s) return s;
    // The program wrote through its own descriptor: ours still names the same file (unless the
    // program replaced it), so reopen by path for the fsync.
    const int fd = ::open(file.temporary().c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return makeError("{}: the writer left no file: {}", target.string(), std::strerror(errno));
    ::close(file.mFd);
    file.mFd = fd;
    return file.commit();
}

}  // namespace engine
