#include "usage.h"

#include <array>
#include <utility>
#include <vector>

#include <lightscatter/lightscatter.h>

namespace host {
namespace {

// Words wrapped at 88 columns, every line after the first indented by `indent` spaces.
std::string wrapped(const std::vector<std::string>& words, size_t indent, size_t first) {
    std::string text, line;
    size_t room = 88 - first;
    for (const std::string& w : words) {
        if (!line.empty() && line.size() + 1 + w.size() > room) {
            text += line + "\n" + std::string(indent, ' ');
            line.clear();
            room = 88 - indent;
        }
        line += (line.empty() ? "" : " ") + w;
    }
    return text + line + "\n";
}

constexpr const char* kCommonOptions =
    "common options: --device NAME (or LS_DEVICE), --validation, --help (-h)\n";

// The methods and presets and the profiles, from the plugin (methodInfo(), profileNames()).
std::string methodsAndProfiles() {
    std::vector<std::string> words{"methods:", "auto (default),"};
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo()) {
        if (m.presets.empty()) {
            words.push_back(m.name + ",");
            continue;
        }
        // A word per preset, so that the list wraps.
        words.push_back(m.name + " (or its presets:");
        for (size_t i = 0; i < m.presets.size(); ++i)
            words.push_back(m.presets[i].name + (i + 1 < m.presets.size() ? "," : "),"));
    }
    words.push_back("(planes' former name slices is still read); profiles:");
    const std::vector<std::string> profiles = lightscatter::profileNames();
    for (size_t i = 0; i < profiles.size(); ++i)
        words.push_back(profiles[i] + (profiles[i] == "balanced" ? " (default)" : "") +
                        (i + 1 < profiles.size() ? "," : " (with --settings)"));
    return wrapped(words, 0, 0);
}

// Every field of lightscatter::Settings, from the plugin's tables (settingsFields()).
std::string settingsHelp() {
    std::vector<std::string> words{
        "JSON object of lightscatter::Settings' fields by name, each method's nested under its",
        "member ({\"epipolar\": {\"slices\": 512}}) or named in full (\"epipolar.slices\");",
        "fields it leaves out keep the values of --profile, and the frame runs as the custom",
        "profile. The fields:"};
    for (const lightscatter::SettingsField& f : lightscatter::settingsFields()) {
        std::string w = f.name;
        if (!f.choices.empty()) {
            w += " (";
            for (size_t i = 0; i < f.choices.size(); ++i) w += (i ? "|" : "") + f.choices[i];
            w += ")";
        }
        if (f.kind == lightscatter::SettingsField::Kind::Vector4) w += " [4 numbers]";
        words.push_back(w + ",");
    }
    words.back().pop_back();
    words.push_back("(read under their names before 0.4 too: slices, planeCount, ...)");
    return "  --settings FILE.json  " + wrapped(words, 24, 24);
}

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
            "budget [--method NAME] [--profile NAME|all]\n"
            "                    [--settings FILE.json]\n"
            "                    [--size WxH] [--shadow-map N] [--lights LIST]\n"
            "                    [--color FORMAT] [--json]\n",
            "Prints a method's GPU memory per profile without a GPU.\n"
            "  --method NAME       any method or preset (default epipolar)\n"
            "  --profile NAME|all  one profile, or all of them (default)\n"
            "  --size WxH          the screen, 1 to 16384 each (default 2560x1600)\n"
            "  --shadow-map N      the shadow map's size, 1 to 16384 (default: the profile's)\n"
            "  --lights LIST       the frame's lights, comma-separated: sun, spot, point\n"
            "                      (default spot); each has a shadow map where the method\n"
            "                      samples one (a point light a cube map of six). Each\n"
            "                      may add :shadowed or :unshadowed and\n"
            "                      :METHOD (any method or preset, one preset a frame;\n"
            "                      auto by default, or --method where given): the set is\n"
            "                      then budgeted light by light,\n"
            "                      e.g. sun,spot:brute-force,point:unshadowed\n"
            "  --color FORMAT      the engine's color, R16G16B16A16_SFLOAT by default (a\n"
            "                      storage image); a format without storage, such as\n"
            "                      B10G11R11_UFLOAT_PACK32 or R8G8B8A8_SRGB, adds the split\n"
            "                      composite's two screen textures\n"
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
        "steps the scrolling noise's amplitude (0, 0.25, 0.5, 1; the methods that honour it), Esc\n"
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

// The commands that take --settings get its block of every field; the others (bench, pattern) do
// not, as they take no such option.
bool takesSettings(const std::string& name) {
    return name == "render" || name == "graph" || name == "view" || name == "budget";
}

// The commands that name methods and profiles (on the command line, or in bench's configuration)
// end with their list; pattern renders no light scattering and names neither.
bool namesMethods(const std::string& name) {
    return name != "pattern";
}

}  // namespace

std::string usage() {
    std::string text =
        "usage: lightscatter <command> [options]   (lightscatter <command> --help for more)\n";
    for (const Command& c : kCommands) text += std::string("  ") + c.synopsis;
    return text + kCommonOptions + methodsAndProfiles();
}

std::string commandUsage(const std::string& name) {
    for (const Command& c : kCommands) {
        if (name != c.name) continue;
        std::string text = std::string("usage: lightscatter ") + c.synopsis + c.details;
        if (takesSettings(name)) text += settingsHelp();
        text += kCommonOptions;
        return namesMethods(name) ? text + methodsAndProfiles() : text;
    }
    return "";
}

}  // namespace host
