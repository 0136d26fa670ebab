#pragma once
// Writes a whole file and says why when it could not: a full disk shows as a short write(), or only
// at fsync() or close() when the file system defers its blocks, and stdio's buffers hide both (a
// PNG used to end as 0 bytes with success reported). Returns "" when every byte reached the disk,
// otherwise the reason (strerror's words).
#include <cstddef>
#include <string>

namespace host {

std::string writeWholeFile(const std::string& path, const void* data, size_t size);

}  // namespace host
