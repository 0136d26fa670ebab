#pragma once
// A progress line for long commands: once the work has lasted `after`, a line on stderr says which
// phase it is in and for how long, rewritten in place twice a second, and cleared at the end. Only
// when stderr is a terminal: logs and pipes get nothing.
#include <chrono>
#include <condition_variable>
#include <iosfwd>
#include <mutex>
#include <string>
#include <thread>

namespace host {

class ProgressLine {
  public:
    // `sink` and `enabled` are for tests; a command takes the defaults (stderr, if a terminal).
    explicit ProgressLine(std::string first,
                          std::chrono::milliseconds after = std::chrono::milliseconds(2000));
    ProgressLine(std::string first, std::chrono::milliseconds after, std::ostream& sink,
                 bool enabled, std::chrono::milliseconds every = std::chrono::milliseconds(500));
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void phase(std::string what);

  private:
    void run();

    std::ostream& sink_;
    const std::chrono::steady_clock::time_point start_;
    const std::chrono::milliseconds after_, every_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::string phase_;
    bool stop_ = false;
    bool shown_ = false;  // a line is on the terminal, to clear at the end
    std::thread thread_;
};

}  // namespace host
