// A short exclusive section shared by processes, on one or many machines: flock(2) on a lock
// file, waiting until it is free. Read-modify-write of a file several processes update (a job
// manifest, tools/vox/job_manifest.h) happens inside one. The kernel drops the lock when the
// process ends however it ends, so a killed writer never blocks the others; on NFS, Linux maps
// flock to a whole-file POSIX lock, which the server arbitrates between hosts. The same lock is
// taken from a shell with util-linux's `flock FILE command`.
#pragma once

#include <filesystem>

#include "core/error.h"

namespace engine {

class ExclusiveFileLock {
public:
    ExclusiveFileLock() = default;
    ~ExclusiveFileLock();
    ExclusiveFileLock(const ExclusiveFileLock&) = delete;
    ExclusiveFileLock& operator=(const ExclusiveFileLock&) = delete;
    ExclusiveFileLock(ExclusiveFileLock&& other) noexcept : mFd(other.mFd) { other.mFd = -1; }

    // Creates `file` if needed and waits for the lock. The file stays (removing it would race
    // with the next holder).
    static Result<ExclusiveFileLock> acquire(const std::filesystem::path& file);

private:
    explicit ExclusiveFileLock(int fd) : mFd(fd) {}
    int mFd = -1;
};

}  // namespace engine
