#include "temp_files.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace host {
namespace {

// The signal handler may only use async-signal-safe calls: it walks a fixed table of paths that
// are complete before their slot is marked live, and calls unlink() on each.
constexpr int kSlots = 64;
struct Slot {
    std::atomic<bool> claimed{false};
    std::atomic<bool> live{false};
    char path[PATH_MAX] = {};
};
Slot slots[kSlots];
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler reads these flags");

void unlinkLive() {
    for (Slot& s : slots)
        if (s.live.load()) ::unlink(s.path);
}

// The thread that makes and writes the temporaries (the main thread). The handler does its work
// there only: run on another thread (the driver's workers take signals too), it would race with
// the writer, which could create a file again after it was removed.
pthread_t writer;

extern "C" void onFatalSignal(int sig) {
    const int saved = errno;
    if (!::pthread_equal(::pthread_self(), writer)) {
        ::pthread_kill(writer, sig);
        errno = saved;
        return;
    }
    unlinkLive();
    // The default action, so the parent sees the program die of this signal as it would have.
    ::signal(sig, SIG_DFL);
    ::raise(sig);
    errno = saved;
}

// Every signal whose default action ends the process and that comes from outside it (a user, a
// shell, a closed pipe, a timer, a resource limit). The signals a fault raises in the thread that
// made it (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS, SIGTRAP) are left alone: forwarded from another
// thread, the handler would return into the fault.
std::vector<int> endingSignals() {
    std::vector<int> list = {SIGHUP,    SIGINT,  SIGQUIT, SIGPIPE, SIGALRM,
                             SIGTERM,   SIGUSR1, SIGUSR2, SIGIO,   SIGPROF,
                             SIGVTALRM, SIGXCPU, SIGXFSZ, SIGPWR,  SIGSTKFLT};
    for (int sig = SIGRTMIN; sig <= SIGRTMAX; ++sig) list.push_back(sig);
    return list;
}

const std::vector<int>& caughtSignals() {
    static const std::vector<int> caught = endingSignals();
    return caught;
}

void installHandlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        writer = ::pthread_self();
        for (int sig : caughtSignals()) {
            struct sigaction current {};
            if (::sigaction(sig, nullptr, &current) != 0) continue;
            // Ignored (nohup, a background job's SIGINT and SIGQUIT) stays ignored; a handler
            // someone else installed (a sanitizer, a profiler) stays theirs.
            if (current.sa_handler != SIG_DFL) continue;
            struct sigaction action {};
            action.sa_handler = onFatalSignal;
            sigemptyset(&action.sa_mask);
            action.sa_flags = SA_NODEFER;  // the re-raise inside the handler takes effect at once
            ::sigaction(sig, &action, nullptr);
        }
    });
}

int claimSlot(const std::string& path) {
    if (path.size() >= PATH_MAX) throw std::runtime_error(path + ": path too long");
    for (int i = 0; i < kSlots; ++i) {
        bool expected = false;
        if (!slots[i].claimed.compare_exchange_strong(expected, true)) continue;
        std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
        slots[i].live.store(true);
        return i;
    }
    throw std::runtime_error(path + ": more than " + std::to_string(kSlots) +
                             " temporary files at once");
}

void releaseSlot(int i) {
    if (i < 0) return;
    slots[i].live.store(false);
    slots[i].claimed.store(false);
}

}  // namespace

TempFile::TempFile(const std::string& target, const std::string& option)
    : target_(target), option_(option) {
    installHandlers();
    // Blocked while the file exists but is not yet registered, so a signal cannot slip between (the
    // handler runs on this thread only).
    sigset_t fatal, previous;
    sigemptyset(&fatal);
    for (int sig : caughtSignals()) sigaddset(&fatal, sig);
    ::pthread_sigmask(SIG_BLOCK, &fatal, &previous);
    // Not mkstemp: its 0600 would become the finished file's mode; 0666 leaves it to the umask.
    static std::atomic<unsigned> counter{0};
    int fd = -1, error = 0;
    std::string name;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        name = target + "." + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
               ".partial";
        fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        error = errno;
        if (fd < 0 && error != EEXIST) break;
    }
    if (fd >= 0) {
        ::close(fd);
        try {
            slot_ = claimSlot(name);
        } catch (...) {
            ::unlink(name.c_str());
            ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
            throw;
        }
    }
    ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    if (fd < 0) {
        std::string dir = std::filesystem::path(target).parent_path().string();
        if (dir.empty()) dir = ".";
        throw std::runtime_error(option + " " + target + ": cannot create a file in " + dir + ": " +
                                 std::strerror(error));
    }
    path_ = name;
}

TempFile::~TempFile() {
    if (!moved_) ::unlink(path_.c_str());
    releaseSlot(slot_);
}

void TempFile::moveIntoPlace() {
    if (::rename(path_.c_str(), target_.c_str()) != 0) {
        const int error = errno;
        throw std::runtime_error(
            option_ + " " + target_ +
            ": cannot move the finished file into place: " + std::strerror(error));
    }
    moved_ = true;
    releaseSlot(slot_);
    slot_ = -1;
}

}  // namespace host
