#include "progress_line.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "terminal_text.h"

namespace host {
namespace {

// A phase names the user's files ("loading PATH"): the line is rewritten in place on a terminal,
// so a path's control characters would act on it, and a long one would wrap and leave its first
// rows behind at each rewrite.
constexpr size_t kMaxPhaseChars = 200;

std::string printable(const std::string& phase) {
    return terminalText(phase, kMaxPhaseChars);
}

}  // namespace

ProgressLine::ProgressLine(std::string first, std::chrono::milliseconds after)
    : ProgressLine(std::move(first), after, std::cerr, isatty(STDERR_FILENO) == 1) {}

ProgressLine::ProgressLine(std::string first, std::chrono::milliseconds after, std::ostream& sink,
                           bool enabled, std::chrono::milliseconds every)
    : sink_(sink),
      start_(std::chrono::steady_clock::now()),
      after_(after),
      every_(every),
      phase_(printable(first)) {
    if (enabled) thread_ = std::thread([this] { run(); });
}

ProgressLine::~ProgressLine() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    // The line is cleared, so that what the command prints next starts on a clean line.
    if (shown_) sink_ << "\r\033[K" << std::flush;
}

void ProgressLine::phase(std::string what) {
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = printable(what);
}

void ProgressLine::run() {
    std::unique_lock<std::mutex> lock(mutex_);
    if (wake_.wait_until(lock, start_ + after_, [this] { return stop_; })) return;
    while (!stop_) {
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        char elapsed[32];
        std::snprintf(elapsed, sizeof elapsed, "%.1f s", s);
        sink_ << "\r\033[Klightscatter: " << phase_ << " (" << elapsed << ")" << std::flush;
        shown_ = true;
        wake_.wait_for(lock, every_, [this] { return stop_; });
    }
}

}  // namespace host
