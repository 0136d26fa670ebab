#include "csv_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "file_bytes.h"

namespace host::bench {

std::string csvRow(const std::vector<std::string>& fields) {
    std::string row;
    for (size_t i = 0; i < fields.size(); ++i) {
        if (i) row += ',';
        const std::string& f = fields[i];
        if (f.find_first_of(",\"\r\n") == std::string::npos) {
            row += f;
            continue;
        }
        row += '"';
        for (char c : f) {
            if (c == '"') row += '"';
            row += c;
        }
        row += '"';
    }
    return row + "\n";
}

std::string csvNumber(const char* format, double value) {
    char buf[64];
    const int n = std::snprintf(buf, sizeof buf, format, value);
    if (n >= 0 && static_cast<size_t>(n) < sizeof buf) return buf;
    std::string big(static_cast<size_t>(n) + 1, '\0');
    std::snprintf(big.data(), big.size(), format, value);
    big.resize(static_cast<size_t>(n));
    return big;
}

CsvFile::CsvFile(const std::string& path, const std::string& header) : path_(path) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0)
        throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(errno));
    append(header + "\n");
}

CsvFile::~CsvFile() {
    if (fd_ >= 0) ::close(fd_);
}

void CsvFile::append(const std::string& row) {
    const int error = writeAndSync(fd_, row.data(), row.size(), static_cast<off_t>(size_));
    if (error != 0) {
        // No half row for a reader (or the next run's report) to misread; if even this fails,
        // the error below is still the one to report.
        [[maybe_unused]] const int cut = ::ftruncate(fd_, size_);
        throw std::runtime_error(path_ + ": cannot write: " + std::strerror(error));
    }
    size_ += static_cast<long long>(row.size());
}

}  // namespace host::bench
