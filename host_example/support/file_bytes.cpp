#include "file_bytes.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace host {

int writeAndSync(int fd, const void* data, size_t size, off_t offset) {
    const char* at = static_cast<const char*>(data);
    size_t left = size;
    while (left > 0) {
        const ssize_t n = ::pwrite(fd, at, left, offset);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno;
        // A write that takes nothing without an error would loop for ever.
        if (n == 0) return ENOSPC;
        at += n;
        offset += n;
        left -= static_cast<size_t>(n);
    }
    // EINVAL, EROFS: a file that cannot be synced (its bytes are written; nothing to wait for).
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) return errno;
    return 0;
}

std::string writeWholeFile(const std::string& path, const void* data, size_t size) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) return std::strerror(errno);
    int error = writeAndSync(fd, data, size, 0);
    if (::close(fd) != 0 && error == 0 && errno != EINTR) error = errno;
    return error ? std::strerror(error) : std::string();
}

}  // namespace host
