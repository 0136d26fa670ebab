// lightscatter graph SCENE.json --dot|--json [--method NAME] [--profile NAME]
//   [--settings FILE.json] [--size WxH]
#include <iostream>

#include "command_options.h"
#include "commands.h"

namespace host {

int runGraph(Args& args) {
    const bool dot = args.flag("--dot");
    const bool json = args.flag("--json");
    SceneOptions o = takeSceneOptions(args, "320x180");
    const std::string scenePath = args.positional("SCENE.json");
    args.finish();
    if (dot == json) throw std::runtime_error("graph: give exactly one of --dot or --json");
    const SceneDesc scene = loadSceneFile(scenePath);
    const MeshData mesh = loadSceneMeshes(scene);
    for (const auto& w : mesh.warnings) std::cerr << "lightscatter: warning: " << w << "\n";
    o.device.announce = false;
    rg::Device device(o.device);
    EngineRenderer renderer(device, scene, mesh, sceneSize(o, {320, 180}));
    renderer.render(o.render);  // the plugin compiles its graph for the frame it is given
    std::cout << (dot ? renderer.plugin().graphDot() : renderer.plugin().graphJson());
    return device.messageCount() > 0 ? 3 : 0;
}

}  // namespace host
