// Outputs all or nothing: clashes between outputs and with inputs refused before anything is
// written, unwritable folders found at once, and a failure leaving the earlier files as they were
// with no temporary behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "host_test_helpers.h"
#include "output_set.h"

namespace {

namespace fs = std::filesystem;

class HostOutputSet : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("host_outputs_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(path(name)) << text;
    }
    std::string read(const std::string& name) const { return host_test::readAll(path(name)); }
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    std::string addError(host::OutputSet& set, const std::string& option,
                         const std::string& p) const {
        try {
            set.add(option, p);
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "(no error)";
    }

    fs::path dir_;
};

TEST_F(HostOutputSet, TheSameFileTwiceIsRefused) {
    host::OutputSet set;
    set.add("--out", path("a.exr"));
    EXPECT_EQ(addError(set, "--inscatter", dir_.string() + "/./sub/../a.exr"),
              "--inscatter " + dir_.string() + "/./sub/../a.exr: is the same file as --out " +
                  path("a.exr") + "; give each output its own file");
    fs::create_directory_symlink(dir_, dir_ / "link");
    EXPECT_NE(addError(set, "--timings", path("link/a.exr")).find("is the same file as --out"),
              std::string::npos);
    write("b.exr", "old");
    fs::create_hard_link(path("b.exr"), path("hard.exr"));
    set.add("--inscatter", path("b.exr"));
    EXPECT_NE(addError(set, "--timings", path("hard.exr")).find("is the same file as --inscatter"),
              std::string::npos);
    EXPECT_EQ(files(), (std::vector<std::string>{"b.exr", "hard.exr", "link"}));  // nothing written
}

TEST_F(HostOutputSet, AnInputIsNeverOverwritten) {
    write("scene.json", "{}");
    host::OutputSet set;
    set.addInput("the scene file", path("scene.json"));
    EXPECT_EQ(addError(set, "--timings", path("scene.json")),
              "--timings " + path("scene.json") + ": is the scene file (" + path("scene.json") +
                  "); an output must not overwrite an input");
    EXPECT_EQ(read("scene.json"), "{}");
}

TEST_F(HostOutputSet, UnwritablePlacesAreFoundBeforeAnyWork) {
    host::OutputSet set;
    EXPECT_EQ(addError(set, "--timings", "/proc/t.json"),
              "--timings /proc/t.json: cannot create a file in /proc: No such file or directory");
    EXPECT_EQ(addError(set, "--out", path("missing/x.png")),
              "--out " + path("missing/x.png") + ": cannot create a file in " + path("missing") +
                  ": No such file or directory");
    fs::create_directory(dir_ / "folder.png");
    EXPECT_EQ(addError(set, "--out", path("folder.png")),
              "--out " + path("folder.png") + ": is a directory; give a file name");
    EXPECT_EQ(addError(set, "--out", "/dev/null"),
              "--out /dev/null: exists and is not a regular file; give a file name");
    EXPECT_EQ(files(), (std::vector<std::string>{"folder.png"}));  // the probes are gone
}

TEST_F(HostOutputSet, AFailedWriteLeavesTheEarlierFilesAsTheyWere) {
    write("a.png", "old image");
    write("t.json", "old timings");
    {
        host::OutputSet set;
        set.add("--out", path("a.png"));
        set.add("--timings", path("t.json"));
        set.writeText(path("a.png"), "new image");
        // A disk that fills after 16 bytes: the write stops short with EFBIG (SIGXFSZ ignored).
        const std::string bytes(4096, 'x');
        const auto previous = ::signal(SIGXFSZ, SIG_IGN);
        struct rlimit limit {};
        ::getrlimit(RLIMIT_FSIZE, &limit);
        const struct rlimit small { 16, limit.rlim_max };
        ::setrlimit(RLIMIT_FSIZE, &small);
        std::string message;
        try {
            set.write(path("t.json"), std::vector<uint8_t>(bytes.begin(), bytes.end()), "JSON");
        } catch (const std::runtime_error& e) {
            message = e.what();
        }
        ::setrlimit(RLIMIT_FSIZE, &limit);
        ::signal(SIGXFSZ, previous);
        EXPECT_EQ(message,
                  "--timings " + path("t.json") + ": cannot write the JSON: File too large");
    }  // dropped without commit, as when the command throws
    EXPECT_EQ(read("a.png"), "old image");
    EXPECT_EQ(read("t.json"), "old timings");
    EXPECT_EQ(files(), (std::vector<std::string>{"a.png", "t.json"}));
}

TEST_F(HostOutputSet, CommitReplacesEveryOutputTogether) {
    write("a.png", "old image");
    host::OutputSet set;
    set.add("--out", path("a.png"));
    set.add("--timings", path("t.json"));
    set.writeText(path("a.png"), "new image");
    set.writeText(path("t.json"), "new timings");
    EXPECT_EQ(read("a.png"), "old image");  // nothing moves before the commit
    set.commit();
    EXPECT_EQ(read("a.png"), "new image");
    EXPECT_EQ(read("t.json"), "new timings");
    EXPECT_EQ(files(), (std::vector<std::string>{"a.png", "t.json"}));
}

}  // namespace
