#pragma once
// Writes a whole file and says why when it could not: a full disk shows as a short write(), or only
// at fsync() or close() when the file system defers its blocks, and stdio's buffers hide both (a
// PNG used to end as 0 bytes with success reported).
#include <sys/types.h>

#include <cstddef>
#include <string>

namespace host {

// Returns "" when every byte reached the disk, otherwise the reason (strerror's words).
std::string writeWholeFile(const std::string& path, const void* data, size_t size);

// Writes `size` bytes at `offset` of the open file `fd`, through short writes and interruptions,
// then syncs it: 0 when every byte reached the disk, otherwise the errno that stopped it.
int writeAndSync(int fd, const void* data, size_t size, off_t offset);

}  // namespace host
