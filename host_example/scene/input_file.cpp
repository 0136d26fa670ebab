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

namespace {

// Reads into `bytes` (a std::string or a byte vector) sized once from the file's size: the whole
// file is held once, never in a buffer grown by copying (a 1 GiB buffer used to pass through a
// 2 GiB one on its way, and a copy into a vector after that).
template <class Bytes>
void readInto(Bytes& bytes, const std::string& path, const std::string& what, uint64_t cap) {
    auto fail = [&](const std::string& why) {
        throw InputFileError(path + ": " + what + " " + why);
    };
    if (path.empty()) fail("has an empty path");
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer before the check
    // below could refuse it.
    Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0) {
        const int error = errno;
        const std::string why = whyNotARegularFile(path);
        if (!why.empty()) fail(why);
        fail(std::string("cannot be opened: ") + std::strerror(error));
    }
    struct stat st {};
    if (::fstat(file.fd, &st) != 0) fail(std::string("cannot be read: ") + std::strerror(errno));
    if (const std::string why = kindOf(st.st_mode); !why.empty()) fail(why);
    const auto tooLarge = [&] {
        fail("is larger than the " + byteSize(cap) + " read for a " + what);
    };
    if (uint64_t(st.st_size) > cap) tooLarge();
    bytes.resize(size_t(st.st_size));
    size_t have = 0;
    // The file may change while it is read: reading stops at the end it really has. One more read
    // into a small buffer tells whether it grew; only then does `bytes` grow, up to one byte past
    // the cap, enough to know it grew beyond it.
    for (;;) {
        ssize_t n;
        if (have < bytes.size()) {
            n = ::read(file.fd, bytes.data() + have, bytes.size() - have);
        } else {
            char probe[4096];
            n = ::read(file.fd, probe, sizeof probe);
            if (n > 0) {
                if (uint64_t(have) + uint64_t(n) > cap) tooLarge();
                bytes.resize(std::min<uint64_t>(cap + 1, uint64_t(have) * 2 + 4096));
                std::memcpy(bytes.data() + have, probe, size_t(n));
            }
        }
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(std::string("cannot be read: ") + std::strerror(errno));
        }
        if (n == 0) break;
        have += size_t(n);
    }
    if (have > cap) tooLarge();
    bytes.resize(have);
}

}  // namespace

std::string readInputFile(const std::string& path, const std::string& what, uint64_t cap) {
    std::string bytes;
    readInto(bytes, path, what, cap);
    return bytes;
}

std::vector<unsigned char> readInputBytes(const std::string& path, const std::string& what,
                                          uint64_t cap) {
    std::vector<unsigned char> bytes;
    readInto(bytes, path, what, cap);
    return bytes;
}

}  // namespace host
