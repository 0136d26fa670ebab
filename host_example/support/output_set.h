#pragma once
// The files one command writes, all or nothing. Each output is checked when it is added, before
// any rendering: not the same file as another output or as an input, not a directory or device,
// and its folder writable (a temporary is created there and removed). The results are written to
// temporaries beside their targets and moved into place only when every one was written; any
// failure, or a signal, removes the temporaries and leaves the files that were there untouched.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "temp_files.h"

namespace host {

class OutputSet {
  public:
    // Files the command reads: an output that is one of them is refused. `what` names it in the
    // message ("the scene file", "a glTF file the scene reads").
    void addInput(const std::string& what, const std::string& path);
    // Throws when `path` is another output, an input, a file that a scene or glTF in its folder
    // reads (referenced_files.h), or not a regular file; `option` names it ("--out"). For outputs
    // written as the command goes (the benchmark's), checked here but not added.
    void check(const std::string& option, const std::string& path) const;
    // check(), and throws when the file's folder is not writable; the output is then written with
    // write() and moved into place by commit().
    void add(const std::string& option, const std::string& path);

    // Writes an added output's bytes to its temporary; throws naming the option, the file, `what`
    // ("PNG") and why (a full disk: every byte is checked to reach it), removing the temporary.
    void write(const std::string& path, const std::vector<uint8_t>& bytes, const std::string& what);
    void writeText(const std::string& path, const std::string& text);
    // Moves every output into place; call once all were written.
    void commit();

  private:
    struct Input {
        std::string what, path;
    };
    struct Output {
        std::string option, path;
        std::unique_ptr<TempFile> temp;
        bool written = false;
    };
    Output& find(const std::string& path);
    std::vector<Input> inputs_;
    std::vector<Output> outputs_;
};

// True when the two paths name the same file: the same inode when both exist, otherwise the same
// path once made absolute and its symbolic links resolved.
bool sameFile(const std::string& a, const std::string& b);

}  // namespace host
