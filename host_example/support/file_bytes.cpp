#include "file_bytes.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace host {

std::string writeWholeFile(const std::string& path, const void* data, size_t size) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) return std::strerror(errno);
    const char* at = static_cast<const char*>(data);
    size_t left = size;
    int error = 0;
    while (left > 0 && error == 0) {
        const ssize_t n = ::write(fd, at, left);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) error = errno;
        // A write that takes nothing without an error would loop for ever.
        else if (n == 0)
            error = ENOSPC;
        else {
            at += n;
            left -= static_cast<size_t>(n);
        }
    }
    if (error == 0 && ::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) error = errno;
    if (::close(fd) != 0 && error == 0 && errno != EINTR) error = errno;
    return error ? std::strerror(error) : std::string();
}

}  // namespace host
