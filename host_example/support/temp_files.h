#pragma once
// Temporary files beside the outputs they become. While one exists, every signal that would end the
// program (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1, SIGALRM, SIGXFSZ, ...; not the
// faults) removes it before the program dies of that signal, so an interrupted write leaves nothing
// behind. A signal ignored when the program started stays ignored.
// They are made and written by one thread (the main thread): the handler does its work there.
#include <string>

namespace host {

class TempFile {
  public:
    // Creates an empty file "TARGET.PID-N.partial" in the target's directory, or throws naming
    // `option` (e.g. "--out"), the target and why (a directory that does not exist, no write
    // permission, ...). Creating it is also the check that the directory is writable.
    TempFile(const std::string& target, const std::string& option);
    ~TempFile();  // removes the temporary unless it was moved into place
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;

    const std::string& path() const { return path_; }
    const std::string& target() const { return target_; }
    void moveIntoPlace();  // renames it to the target; throws naming the target

  private:
    std::string target_, option_, path_;
    int slot_ = -1;
    bool moved_ = false;
};

}  // namespace host
