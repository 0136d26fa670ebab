#pragma once
// Reading the files a user names (scenes, glTF and their buffers and images, configurations): only
// regular files, and never more than a cap, so that /dev/zero, a FIFO or a directory is one clear
// error instead of a hang or an endless allocation.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace host {

class InputFileError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

constexpr uint64_t kMiB = uint64_t{1} << 20;
constexpr uint64_t kGiB = uint64_t{1} << 30;

// The whole file, or throws InputFileError "PATH: <what> ..." naming the rule broken (missing, a
// directory, not a regular file, larger than `cap`, unreadable). `what` is e.g. "scene file".
std::string readInputFile(const std::string& path, const std::string& what, uint64_t cap);
// The same as bytes, for data that is kept as it is read (a glTF's buffers).
std::vector<unsigned char> readInputBytes(const std::string& path, const std::string& what,
                                          uint64_t cap);

// Why `path` cannot be read as a regular file ("does not exist", "is a directory", "is a character
// device, not a regular file", ...), or "" when it is a regular file.
std::string whyNotARegularFile(const std::string& path);

// "16 MiB", "1 GiB", "512 bytes".
std::string byteSize(uint64_t bytes);

}  // namespace host
