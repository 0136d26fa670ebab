// lightscatter: the host example's command line.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"
#include "rendergraph/device.h"

namespace {

const char* kUsage =
    "usage: lightscatter <command> [options]\n"
    "  render SCENE.json [--out FILE.png|.exr] [--inscatter FILE.exr] [--method NAME]\n"
    "                    [--profile NAME] [--size WxH] [--timings FILE.json] [--frames N]\n"
    "  budget [--profile NAME|all] [--size WxH] [--shadow-map N] [--json]\n"
    "  graph SCENE.json --dot|--json [--method NAME] [--profile NAME] [--size WxH]\n"
    "  view SCENE.json [--method NAME] [--profile NAME] [--size WxH] [--frames N]\n"
    "  bench [--config FILE.json] [--out DIR]\n"
    "  pattern [--out FILE.png] [--size WxH] [--report FILE.json] [--dot FILE.dot]\n"
    "common options: --device NAME (or LS_DEVICE), --validation\n"
    "methods: epipolar (default), brute-force; profiles: high-quality, balanced (default),\n"
    "high-performance, low-high-quality, low-balanced, low-high-performance\n";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        std::cout << kUsage;
        return words.empty() ? 2 : 0;
    }
    const std::string command = words[0];
    try {
        host::Args args(std::vector<std::string>(words.begin() + 1, words.end()));
        int code = 2;
        if (command == "render") code = host::runRender(args);
        else if (command == "budget") code = host::runBudget(args);
        else if (command == "graph") code = host::runGraph(args);
        else if (command == "view") code = host::runView(args);
        else if (command == "pattern") code = host::runPattern(args);
        else if (command == "bench") code = host::runBench(args);
        else {
            std::cerr << "lightscatter: unknown command '" << command
                      << "' (known: render, budget, graph, view, bench, pattern)\n";
            return 2;
        }
        // The command's device is gone by now: what the layer said while it was destroyed (objects
        // left alive) counts too.
        if (code == 0 && rg::validationMessagesInProcess() > 0) {
            std::cerr << "lightscatter: the validation layer reported " << rg::validationMessagesInProcess()
                      << " message(s)\n";
            return 3;
        }
        return code;
    } catch (const std::exception& e) {
        std::cerr << "lightscatter: " << e.what() << "\n";
        return 1;
    }
}
