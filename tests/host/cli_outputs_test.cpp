// Outputs (issue #8): clashing paths and inputs refused before rendering, an unwritable output
// found before rendering, all outputs or none, and no temporary left by a signal that ends the
// program.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cli_runner.h"
#include "host_test_helpers.h"

extern char** environ;

using cli_test::expectFailure;
using cli_test::expectNoTemporaries;
using cli_test::path;
using cli_test::run;
using cli_test::scene;
using cli_test::writeFile;

namespace {

namespace fs = std::filesystem;

std::string read(const std::string& name) {
    return host_test::readAll(path(name));
}

bool anyTemporary() {
    for (const auto& e : fs::directory_iterator(cli_test::scratch()))
        if (e.path().string().find(".partial") != std::string::npos) return true;
    return false;
}

}  // namespace

TEST(CliOutputs, ClashingPathsAreRefusedBeforeRendering) {
    const std::string atrium = scene("atrium");
    expectFailure(run("render " + atrium + " --out a.exr --inscatter ./a.exr"),
                  "--inscatter ./a.exr: is the same file as --out a.exr");
    expectFailure(run("render " + atrium + " --out a.png --timings sub/../a.png"),
                  "is the same file as --out a.png");
    expectFailure(run("pattern --out p.png --dot p.png"),
                  "--dot p.png: is the same file as --out p.png");
    EXPECT_FALSE(cli_test::exists("a.exr"));
    EXPECT_FALSE(cli_test::exists("a.png"));
}

TEST(CliOutputs, AnInputIsNeverOverwritten) {
    fs::copy_file(scene("atrium"), path("mine.json"), fs::copy_options::overwrite_existing);
    // The copy's glTF is beside the original: make its path absolute.
    std::string text = read("mine.json");
    text.replace(text.find("\"atrium.gltf\""), 13,
                 "\"" + std::string(LS_SOURCE_DIR) + "/scenes/atrium.gltf\"");
    writeFile("mine.json", text);
    expectFailure(run("render mine.json --size 8x8 --timings mine.json"),
                  "--timings mine.json: is the scene file (mine.json); an output must not "
                  "overwrite an input");
    EXPECT_EQ(read("mine.json"), text);
    expectFailure(run("render mine.json --size 8x8 --out " + std::string(LS_SOURCE_DIR) +
                      "/scenes/atrium_floor.png"),
                  "is a file the scene reads");
    writeFile("settings.json", "{}");
    expectFailure(
        run("render mine.json --size 8x8 --settings settings.json --timings settings.json"),
        "is the settings file");
    EXPECT_EQ(read("settings.json"), "{}");
}

// A light's cookie is an input too: the scene's own (render's inputs), and another scene's in the
// output's folder (the folder's scan).
TEST(CliOutputs, ACookieIsNeverOverwritten) {
    const std::string png = std::string(LS_SOURCE_DIR) + "/scenes/stained_glass_cookie.png";
    fs::copy_file(png, path("glass.png"), fs::copy_options::overwrite_existing);
    writeFile("glass.json", R"({"light": {"type": "spot", "shadowMapSize": 0,
        "cookie": "glass.png"}})");
    const auto size = fs::file_size(path("glass.png"));
    expectFailure(run("render glass.json --size 8x8 --out glass.png"),
                  "--out glass.png: is a file the scene reads (" + path("glass.png") +
                      "); an output must not overwrite an input");
    expectFailure(run("render " + scene("point_fog") + " --size 8x8 --out glass.png"),
                  "--out glass.png: is a file that glass.json reads");
    EXPECT_EQ(fs::file_size(path("glass.png")), size);
}

TEST(CliOutputs, AnUnwritableOutputFailsBeforeAnythingIsWritten) {
    writeFile("old.png", "the previous image");
    const auto r =
        run("render " + scene("atrium") + " --size 8x8 --out old.png --timings /proc/t.json");
    expectFailure(r, "--timings /proc/t.json: cannot create a file in /proc");
    EXPECT_EQ(r.out.find("using Vulkan device"), std::string::npos) << "rendered first: " << r.out;
    EXPECT_EQ(read("old.png"), "the previous image");
    expectFailure(run("render " + scene("atrium") + " --size 8x8 --out no/such/dir/x.png"),
                  "--out no/such/dir/x.png: cannot create a file in no/such/dir");
    expectNoTemporaries();
}

TEST(CliOutputs, EveryOutputIsReplacedTogether) {
    writeFile("all.png", "old");
    writeFile("all.json", "old");
    const auto r = run("render " + scene("atrium") +
                       " --size 16x9 --out all.png --timings all.json --validation");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(read("all.png"), "old");
    EXPECT_NE(read("all.json"), "old");
    expectNoTemporaries();
}

// The temporaries exist while the images are encoded. Once the device is announced (the outputs'
// checks, with their own brief temporaries, are over), the program is stopped when a temporary
// appears, sent `sig`, and let go. Returns its wait status, or -1 when it finished before a
// temporary was seen. With `ignored`, the program starts with `sig` ignored, as a background job
// starts with SIGINT and SIGQUIT ignored.
static int renderAndSignal(const std::string& out, int sig, bool ignored) {
    const std::string atrium = scene("atrium");
    std::vector<std::string> words = {LS_CLI,
                                      "render",
                                      atrium,
                                      "--size",
                                      "1280x720",
                                      "--out",
                                      out + ".png",
                                      "--inscatter",
                                      out + ".exr",
                                      "--profile",
                                      "low-high-performance",
                                      "--validation"};
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, cli_test::scratch().c_str());
    const std::string log = path(out + ".log");
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    // The child inherits an ignored signal (posix_spawn keeps SIG_IGN across exec).
    struct sigaction previous {};
    if (ignored) {
        struct sigaction ignore {};
        ignore.sa_handler = SIG_IGN;
        ::sigaction(sig, &ignore, &previous);
    }
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, LS_CLI, &actions, nullptr, argv.data(), environ);
    if (ignored) ::sigaction(sig, &previous, nullptr);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return -1;
    bool caught = false;
    const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(3);
    while (std::chrono::steady_clock::now() < until) {
        if (read(out + ".log").find("using Vulkan device") != std::string::npos && anyTemporary()) {
            ::kill(pid, SIGSTOP);
            caught = anyTemporary();  // not already moved into place or removed
            if (caught) ::kill(pid, sig);
            ::kill(pid, SIGCONT);
            if (caught) break;
        }
        int status = 0;
        if (::waitpid(pid, &status, WNOHANG) == pid) return -1;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return caught ? status : -1;
}

// Every signal that ends the program by default, SIGQUIT, SIGPIPE, SIGUSR1 and SIGALRM as much as
// SIGINT (issue #42: those four left a 5 MB temporary).
TEST(CliOutputs, ASignalWhileWritingLeavesNoTemporary) {
    // SIGQUIT's default action dumps core: not into the scratch folder.
    const struct rlimit noCore { 0, 0 };
    ::setrlimit(RLIMIT_CORE, &noCore);
    for (int sig : {SIGINT, SIGQUIT, SIGPIPE, SIGUSR1, SIGALRM}) {
        SCOPED_TRACE(strsignal(sig));
        const std::string out = "signal" + std::to_string(sig);
        const int status = renderAndSignal(out, sig, false);
        ASSERT_NE(status, -1) << "the program finished before a temporary was seen";
        EXPECT_TRUE(WIFSIGNALED(status)) << status;
        EXPECT_EQ(WTERMSIG(status), sig);
        EXPECT_FALSE(anyTemporary());
        EXPECT_FALSE(cli_test::exists(out + ".png"));
        EXPECT_FALSE(cli_test::exists(out + ".exr"));
    }
}

// A signal ignored when the program starts stays ignored: the render goes on and writes its files.
TEST(CliOutputs, AnIgnoredSignalStaysIgnored) {
    const std::string out = "ignored";
    const int status = renderAndSignal(out, SIGQUIT, true);
    ASSERT_NE(status, -1) << "the program finished before a temporary was seen";
    EXPECT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 0) << read(out + ".log");
    EXPECT_FALSE(anyTemporary());
    EXPECT_TRUE(cli_test::exists(out + ".png"));
    EXPECT_TRUE(cli_test::exists(out + ".exr"));
}
