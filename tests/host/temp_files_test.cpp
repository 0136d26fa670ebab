// Temporaries are removed when SIGINT or SIGTERM ends the program while they exist (they used to
// stay behind as x.png.partial), and the program still dies of the signal.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "temp_files.h"

namespace {

namespace fs = std::filesystem;

// Runs `body` in a child process; returns its wait status.
int inChild(const std::function<void()>& body) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        body();
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
}

}  // namespace

TEST(HostTempFiles, ASignalRemovesTheTemporariesAndStillEndsTheProgram) {
    const fs::path dir = fs::temp_directory_path() / ("host_temp_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (int sig : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(sig);
        const int status = inChild([&] {
            host::TempFile a((dir / "x.png").string(), "--out");
            host::TempFile b((dir / "x.exr").string(), "--inscatter");
            std::ofstream(a.path()) << "half an image";
            ::raise(sig);
            ::_exit(0);  // not reached: the signal ends the program
        });
        EXPECT_TRUE(WIFSIGNALED(status)) << status;
        EXPECT_EQ(WTERMSIG(status), sig);
        EXPECT_TRUE(fs::is_empty(dir)) << fs::directory_iterator(dir)->path();
    }
    fs::remove_all(dir);
}

TEST(HostTempFiles, MovedIntoPlaceOrRemoved) {
    const fs::path dir =
        fs::temp_directory_path() / ("host_temp_place_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string kept;
    {
        host::TempFile t((dir / "a.txt").string(), "--out");
        kept = t.path();
        EXPECT_EQ(kept.rfind((dir / "a.txt.").string(), 0), 0u) << kept;
        EXPECT_TRUE(fs::exists(kept));
        std::ofstream(t.path()) << "done";
        t.moveIntoPlace();
    }
    EXPECT_TRUE(fs::exists(dir / "a.txt"));
    EXPECT_FALSE(fs::exists(kept));
    { host::TempFile dropped((dir / "b.txt").string(), "--out"); }
    EXPECT_FALSE(fs::exists(dir / "b.txt"));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    fs::remove_all(dir);
}
