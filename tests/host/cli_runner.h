#pragma once
// Runs the lightscatter command line as a user would, capturing its exit code and output.
#include <string>

namespace cli_test {

struct Result {
    int exitCode = -1;
    std::string out;  // stdout and stderr together
};

// `arguments` is appended to the binary's path; the working directory is a fresh temporary folder,
// also returned by scratch().
Result run(const std::string& arguments, const std::string& prefix = "");
const std::string& scratch();
std::string scene(const std::string& name);  // absolute path of scenes/<name>.json
bool exists(const std::string& path);
std::string path(const std::string& name);  // absolute path of `name` in scratch()
void writeFile(const std::string& name, const std::string& text);  // in scratch()
// One line of output naming `fragment`, and a failing exit code.
void expectFailure(const Result& r, const std::string& fragment);
// No "*.partial" temporary anywhere in scratch().
void expectNoTemporaries();
// The prefix that runs the command under a virtual X server of `screen` (WxHxDepth). Its X
// authority file is `.xvfb-authority` in the folder the command runs in: xvfb-run's own temporary
// folder for it was, once in a CI run, not removed at exit, and xvfb-run then failed (exit 5) a
// command that had succeeded.
std::string xvfb(const std::string& screen = "640x480x24");

}  // namespace cli_test
