// lightscatter: the host example's command line.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"

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
        if (command == "render") return host::runRender(args);
        if (command == "budget") return host::runBudget(args);
        if (command == "graph") return host::runGraph(args);
        if (command == "view") return host::runView(args);
        if (command == "pattern") return host::runPattern(args);
        if (command == "bench") return host::runBench(args);
        std::cerr << "lightscatter: unknown command '" << command
                  << "' (known: render, budget, graph, view, bench, pattern)\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "lightscatter: " << e.what() << "\n";
        return 1;
    }
}
