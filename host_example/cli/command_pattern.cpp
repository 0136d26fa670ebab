// lightscatter pattern: the render-graph runtime's own test pattern (no light scattering).
#include <iostream>

#include "commands.h"
#include "image_io.h"
#include "output_set.h"
#include "rendergraph/demo/test_pattern.h"
#include "rendergraph/report.h"

namespace host {

int runPattern(Args& args) {
    const std::string out = args.take("--out", "pattern.png");
    const auto size = parseSize(args.take("--size", "512x512"), "--size");
    const std::string report = args.take("--report", "");
    const std::string dot = args.take("--dot", "");
    rg::DeviceOptions options;
    options.deviceName = args.take("--device", "");
    options.validation = args.flag("--validation");
    args.finish();

    OutputSet outputs;  // all or nothing, each checked before rendering
    outputs.add("--out", out);
    if (!report.empty()) outputs.add("--report", report);
    if (!dot.empty()) outputs.add("--dot", dot);

    rg::Device device(options);
    rg::demo::TestPatternRenderer renderer(device, size);
    rg::FrameTimings timings;
    const auto pixels = renderer.render(&timings);
    outputs.write(out, encodePng(size.width, size.height, pixels), "PNG");
    if (!report.empty())
        outputs.writeText(report,
                          rg::reportJson(renderer.graph(), renderer.compiled(), &timings).dump(2));
    if (!dot.empty()) outputs.writeText(dot, rg::reportDot(renderer.graph(), renderer.compiled()));
    outputs.commit();
    std::cout << rg::reportText(renderer.graph(), renderer.compiled(), &timings);
    std::cout << "wrote " << out << " (" << size.width << "x" << size.height << ", device '"
              << device.name() << "'" << (device.isCpu() ? ", CPU timings" : "") << ")\n";
    return device.messageCount() > 0 ? 3 : 0;
}

}  // namespace host
