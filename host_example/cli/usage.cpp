#include "usage.h"

#include <array>
#include <utility>

namespace host {
namespace {

const char* kCommon =
    "common options: --device NAME (or LS_DEVICE), --validation, --help (-h)\n"
    "methods: auto (default), epipolar, brute-force, analytic, cone-march, planes (or its\n"
    "former name slices), beam-tree-analytic, beam-tree-sampling, froxels (or a grid\n"
    "preset: froxels-hdrp, the default, froxels-unreal, each with -temporal after it\n"
    "for the temporal mode); profiles:\n"
    "high-quality, balanced (default), high-performance, low-high-quality, low-balanced,\n"
    "low-high-performance, custom (with --settings)\n";

const char* kSettings =
    "  --settings FILE.json  every field of lightscatter::Settings by name (slices,\n"
    "                        samplesPerSlice, initialSampleStep, refinementThreshold,\n"
    "                        inscatterRefinementThreshold, bilateralThreshold, minMaxTrees,\n"
    "                        shadowFilter, fixup, fixupMaxSteps,\n"
    "                        shadowDepthBias, interpolation, shadowMapSize; cone-march's\n"
    "                        coneSamples, coneLimited, coneJitter, shadowSampling; planes'\n"
    "                        planeCount, planeSpacing, planeTarget (float16, float32, rgba8),\n"
    "                        planeScaling, planeRange, planeDither, planeBlur, planeAmbient\n"
    "                        (read under their former names too: slicePlanes, sliceTarget,\n"
    "                        slicePlaneScaling, sliceRange, sliceDither, sliceBlur,\n"
    "                        sliceAmbient),\n"
    "                        noiseAmplitude, noiseScale, noiseVelocity [4 numbers]; seed 004's\n"
    "                        lightModel (full, simplified), simplifiedA0, simplifiedA1;\n"
    "                        froxels' froxelTile, froxelSlices, froxelFarDistance,\n"
    "                        froxelTemporal, froxelHistoryWeight); fields\n"
    "                        it leaves out keep the values of --profile, and the frame runs as\n"
    "                        the custom profile\n";

struct Command {
    const char* name;
    const char* synopsis;  // after "lightscatter "
    const char* details;
};

const std::array kCommands{
    Command{
        "render",
        "render SCENE.json [--out FILE.png|.exr] [--inscatter FILE.exr] [--method NAME]\n"
        "                    [--profile NAME] [--settings FILE.json] [--size WxH]\n"
        "                    [--timings FILE.json] [--frames N] [--count-steps]\n",
        "Renders a scene and writes the image, and optionally Lin alone and the per-pass times.\n"
        "  --out FILE          .png (tone-mapped with the scene's exposure) or .exr (linear);\n"
        "                      default: the scene's name with .png, in the current folder\n"
        "  --inscatter FILE    the in-scattering Lin alone, as a linear .exr\n"
        "  --timings FILE      the plugin's and the engine's pass times as JSON\n"
        "  --size WxH          1 to 16384 each (default 960x540)\n"
        "  --frames N          frames rendered, 1 to 100000 (default 1); the last is written\n"
        "  --count-steps       epipolar: count the ray march's steps (printed, and in --timings)\n"
        "Outputs are written all or nothing: each must be its own file and none may be an "
        "input.\n"},
    Command{"budget",
            "budget [--method epipolar|planes|beam-tree-analytic|beam-tree-sampling|froxels]\n"
            "                    [--profile NAME|all]\n"
            "                    [--settings FILE.json]\n"
            "                    [--size WxH] [--shadow-map N] [--lights LIST]\n"
            "                    [--json]\n",
            "Prints a method's GPU memory per profile without a GPU.\n"
            "  --method NAME       epipolar (default), planes, beam-tree-analytic,\n"
            "                      beam-tree-sampling or froxels (froxels-hdrp,\n"
            "                      froxels-unreal), the methods whose textures depend on the\n"
            "                      profile or the grid\n"
            "  --profile NAME|all  one profile, or all of them (default)\n"
            "  --size WxH          the screen, 1 to 16384 each (default 2560x1600)\n"
            "  --shadow-map N      the shadow map's size, 1 to 16384 (default: the profile's)\n"
            "  --lights LIST       the frame's lights, comma-separated: sun, spot, point\n"
            "                      (default spot); sun and spot have a shadow map, point\n"
            "                      a cube map of six (epipolar; none with the other\n"
            "                      methods). Each may add :shadowed or :unshadowed and\n"
            "                      :METHOD (any method, auto by default, or --method\n"
            "                      where given): the set is then budgeted light by light,\n"
            "                      e.g. sun,spot:brute-force,point:unshadowed\n"
            "  --json              JSON instead of text\n"},
    Command{
        "graph",
        "graph SCENE.json --dot|--json [--method NAME] [--profile NAME] [--settings FILE.json]\n"
        "                   [--size WxH]\n",
        "Prints the plugin's compiled frame graph for a scene, for Graphviz (--dot) or as JSON.\n"
        "  --size WxH          1 to 16384 each (default 320x180)\n"},
    Command{
        "view",
        "view SCENE.json [--method NAME] [--profile NAME] [--settings FILE.json] [--size WxH]\n"
        "                  [--frames N] [--screenshot FILE.png] [--resize-at N --resize-to WxH]\n"
        "                  [--animate-light] [--resizes N] [--memory-log FILE.csv]\n"
        "                  [--no-panel] [--panel-script FILE.json] [--report-log FILE.json]\n",
        "Opens a window (needs a display; xvfb-run -a gives one) with a settings panel: the\n"
        "method, the profile, every setting, the lights and the medium, live; the plugin's\n"
        "report, GPU time per pass and device memory; 'save settings' writes a --settings file.\n"
        "An edit the plugin refuses shows its message and is undone. F1 hides the panel.\n"
        "WASD/QE move, left-drag looks, arrow keys move the selected light (L selects the next\n"
        "of several), M cycles the methods, P cycles profiles, T toggles the min/max trees, N\n"
        "steps the scrolling noise's amplitude (0, 0.25, 0.5, 1; planes and auto only), Esc\n"
        "quits.\n"
        "  --size WxH          1 to 16384 each (default 960x540)\n"
        "  --frames N          close after N frames (1 to 100000)\n"
        "  --screenshot FILE   the last frame as a PNG (needs --frames)\n"
        "  --resize-at N --resize-to WxH  resize the window at frame N (for tests)\n"
        "  --animate-light     move the light on a slow circle, every frame (soak tests)\n"
        "  --resizes N         resize the window N times, evenly over --frames, through 60%, 80%\n"
        "                      and 100% of --size in turn (soak tests)\n"
        "  --memory-log FILE   every 100 frames: frame, resident KiB, device bytes held (CSV)\n"
        "  --no-panel          the window without the settings panel\n"
        "  --panel-script FILE edits made through the panel, one step per frame (needs\n"
        "                      --frames): a JSON array of {\"settings\": {...}, \"method\": ...,\n"
        "                      \"profile\": ..., \"save\": FILE}\n"
        "  --report-log FILE   each frame's report: method, reason, each light's settings\n"},
    Command{
        "bench", "bench [--config FILE.json] [--out DIR]\n",
        "Times every method and profile of a benchmark configuration and measures each against\n"
        "the float64 reference. Every run of the configuration is checked before any renders.\n"
        "  --config FILE       default: bench/small.json of the source tree\n"
        "  --out DIR           default: bench-results\n"},
    Command{"pattern",
            "pattern [--out FILE.png] [--size WxH] [--report FILE.json] [--dot FILE.dot]\n",
            "Renders the render-graph runtime's own test pattern (no light scattering).\n"
            "  --size WxH          1 to 16384 each (default 512x512)\n"},
};

bool takesSettings(const std::string& name) {
    return name == "render" || name == "graph" || name == "view" || name == "budget";
}

}  // namespace

std::string usage() {
    std::string text =
        "usage: lightscatter <command> [options]   (lightscatter <command> --help for more)\n";
    for (const Command& c : kCommands) text += std::string("  ") + c.synopsis;
    return text + kCommon;
}

std::string commandUsage(const std::string& name) {
    for (const Command& c : kCommands) {
        if (name != c.name) continue;
        std::string text = std::string("usage: lightscatter ") + c.synopsis + c.details;
        if (takesSettings(name)) text += kSettings;
        return text + kCommon;
    }
    return "";
}

}  // namespace host
