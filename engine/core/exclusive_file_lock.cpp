// flock(2)-based exclusive sections (core/exclusive_file_lock.h).
#include "core/exclusive_file_lock.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace engine {

ExclusiveFileLock::~ExclusiveFileLock() {
    if (mFd >= 0) ::close(mFd);  // releases the lock
}

Result<ExclusiveFileLock> ExclusiveFileLock::acquire(const std::filesystem::path& file) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0)
        return makeError("{}: cannot create the lock file: {}", file.string(),
                         std::strerror(errno));
    while (::flock(fd, LOCK_EX) != 0) {
        if (errno == EINTR) continue;  // a signal while waiting: wait on
        const int error = errno;
        ::close(fd);
        return makeError("{}: cannot lock: {}", file.string(), std::strerror(error));
    }
    return ExclusiveFileLock(fd);
}

}  // namespace engine
