#pragma once
// bench.csv: rows as RFC 4180 has them (a label with a comma, a quote or a line break used to shift
// every column after it, and a 1024-byte line buffer cut long labels and the rest of the row),
// written as the benchmark goes so that an interrupted one keeps the runs it finished.
#include <string>
#include <vector>

namespace host::bench {

// The fields joined by commas and ended by "\n"; a field holding a comma, a quote, CR or LF
// is quoted and its quotes doubled.
std::string csvRow(const std::vector<std::string>& fields);

// printf-style formatting of one field, any length.
std::string csvNumber(const char* format, double value);

// The file, its header written when opened (replacing what was there). Each row reaches the disk
// whole or not at all: a failed or short write (a full disk) cuts the file back to the rows before
// it and throws naming the file and why.
class CsvFile {
  public:
    CsvFile(const std::string& path, const std::string& header);
    ~CsvFile();
    CsvFile(const CsvFile&) = delete;
    CsvFile& operator=(const CsvFile&) = delete;
    void append(const std::string& row);

  private:
    std::string path_;
    int fd_ = -1;
    long long size_ = 0;  // bytes of whole rows written
};

}  // namespace host::bench
