// lightscatter: the host example's command line.
#include <malloc.h>

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "activity.h"
#include "commands.h"
#include "error_line.h"
#include "rendergraph/device.h"
#include "usage.h"

namespace {

int run(const std::string& command, host::Args& args) {
    if (command == "render") return host::runRender(args);
    if (command == "budget") return host::runBudget(args);
    if (command == "graph") return host::runGraph(args);
    if (command == "view") return host::runView(args);
    if (command == "pattern") return host::runPattern(args);
    if (command == "bench") return host::runBench(args);
    std::cerr << "lightscatter: unknown command '" << command
              << "' (known: render, budget, graph, view, bench, pattern)\n";
    return 2;
}

bool asksForHelp(const std::vector<std::string>& words) {
    for (const std::string& w : words) {
        if (w == "--") return false;  // what follows is a file name, even "--help"
        if (w == "--help" || w == "-h") return true;
    }
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    // Large blocks always come from mmap and go back to the system when freed. glibc otherwise
    // raises its mmap threshold to the size of the largest block freed so far: once a graph's
    // 30 MB transient block (host memory, on lavapipe) was freed at a resize, the next ones came
    // from the heap and fragmented it, and the resident size crept up resize after resize
    // (docs/reliability.md).
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        std::cout << host::usage();
        return words.empty() ? 2 : 0;
    }
    const std::string command = words[0];
    words.erase(words.begin());
    if (asksForHelp(words) && !host::commandUsage(command).empty()) {
        std::cout << host::commandUsage(command);
        return 0;
    }
    try {
        host::Activity running("running lightscatter " + command);
        host::Args args(words);
        const int code = run(command, args);
        // The command's device is gone by now: what the layer said while it was destroyed (objects
        // left alive) counts too.
        if (code == 0 && rg::validationMessagesInProcess() > 0) {
            std::cerr << "lightscatter: the validation layer reported "
                      << rg::validationMessagesInProcess() << " message(s)\n";
            return 3;
        }
        return code;
    } catch (const std::bad_alloc&) {
        // Nothing here may allocate: the activity's text was made before memory ran out.
        std::fputs("lightscatter: out of host memory (an allocation failed) while ", stderr);
        std::fputs(host::currentActivity(), stderr);
        std::fputs("\n", stderr);
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "lightscatter: " << host::errorLine(e.what()) << "\n";
        return 1;
    }
}
