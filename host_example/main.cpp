// lightscatter: the host example's command line.
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli_args.h"
#include "image_io.h"
#include "rendergraph/demo/test_pattern.h"
#include "rendergraph/report.h"

namespace {

const char* kUsage =
    "usage: lightscatter <command> [options]\n"
    "commands:\n"
    "  pattern [--out FILE.png] [--size WxH] [--report FILE.json] [--dot FILE.dot]\n"
    "      renders the render-graph test pattern (several passes, stencil, aliasing)\n"
    "common options: --device NAME (or LS_DEVICE), --validation\n";

int runPattern(host::Args& args) {
    const std::string out = args.take("--out", "pattern.png");
    const auto size = host::parseSize(args.take("--size", "512x512"), "--size");
    const std::string report = args.take("--report", "");
    const std::string dot = args.take("--dot", "");
    rg::DeviceOptions options;
    options.deviceName = args.take("--device", "");
    options.validation = args.flag("--validation");
    args.finish();

    rg::Device device(options);
    rg::demo::TestPatternRenderer renderer(device, size);
    rg::FrameTimings timings;
    const auto pixels = renderer.render(&timings);
    host::writePng(out, size.width, size.height, pixels);
    std::cout << rg::reportText(renderer.graph(), renderer.compiled(), &timings);
    if (!report.empty())
        host::writeTextFile(report, rg::reportJson(renderer.graph(), renderer.compiled(), &timings).dump(2));
    if (!dot.empty()) host::writeTextFile(dot, rg::reportDot(renderer.graph(), renderer.compiled()));
    std::cout << "wrote " << out << " (" << size.width << "x" << size.height << ", device '"
              << device.name() << "'" << (device.isCpu() ? ", CPU timings" : "") << ")\n";
    if (device.messageCount() > 0) {
        std::cerr << "lightscatter: the validation layer reported " << device.messageCount()
                  << " message(s)\n";
        return 3;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h") {
        std::cout << kUsage;
        return words.empty() ? 2 : 0;
    }
    const std::string command = words[0];
    try {
        host::Args args(std::vector<std::string>(words.begin() + 1, words.end()));
        if (command == "pattern") return runPattern(args);
        std::cerr << "lightscatter: unknown command '" << command << "' (known: pattern)\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "lightscatter: " << e.what() << "\n";
        return 1;
    }
}
