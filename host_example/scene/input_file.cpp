#include "scene/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace host {
namespace {

std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "is a directory";
    if (S_ISCHR(mode)) return "is a character device, not a regular file";
    if (S_ISBLK(mode)) return "is a block device, not a regular file";
    if (S_ISFIFO(mode)) return "is a pipe (FIFO), not a regular file";
    if (S_ISSOCK(mode)) return "is a socket, not a regular file";
    return S_ISREG(mode) ? "" : "is not a regular file";
}

// Closes the descriptor on every path out, exceptions included.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

std::string byteSize(uint64_t bytes) {
    if (bytes >= kGiB && bytes % kGiB == 0) return std::to_string(bytes / kGiB) + " GiB";
    if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
    return std::to_string(bytes) + " bytes";
}

std::string whyNotARegularFile(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        return errno == ENOENT || errno == ENOTDIR
                   ? "does not exist"
                   : std::string("cannot be read: ") + std::strerror(errno);
    }
    return kindOf(st.st_mode);
}

std::string readInputFile(const std::string& path, const std::string& what, uint64_t cap) {
    auto fail = [&](const std::string& why) -> std::string {
        throw InputFileError(path + ": " + what + " " + why);
    };
    if (path.empty()) fail("has an empty path");
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer before the check
    // below could refuse it.
    Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0) {
        const int error = errno;
        const std::string why = whyNotARegularFile(path);
        if (!why.empty()) return fail(why);
        return fail(std::string("cannot be opened: ") + std::strerror(error));
    }
    struct stat st {};
    if (::fstat(file.fd, &st) != 0)
        return fail(std::string("cannot be read: ") + std::strerror(errno));
    if (const std::string why = kindOf(st.st_mode); !why.empty()) return fail(why);
    const auto tooLarge = [&] {
        return fail("is larger than the " + byteSize(cap) + " read for a " + what);
    };
    if (uint64_t(st.st_size) > cap) return tooLarge();
    std::string bytes(size_t(st.st_size), '\0');
    size_t have = 0;
    // The file may change while it is read: reading stops at the end it really has, and one byte
    // past the cap is enough to know it grew beyond it.
    for (;;) {
        if (have == bytes.size()) {
            if (have > cap) return tooLarge();
            bytes.resize(std::min<uint64_t>(cap + 1, uint64_t(have) * 2 + 4096));
        }
        const ssize_t n = ::read(file.fd, bytes.data() + have, bytes.size() - have);
        if (n < 0) {
            if (errno == EINTR) continue;
            return fail(std::string("cannot be read: ") + std::strerror(errno));
        }
        if (n == 0) break;
        have += size_t(n);
    }
    if (have > cap) return tooLarge();
    bytes.resize(have);
    return bytes;
}

}  // namespace host
