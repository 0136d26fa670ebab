#include "scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <stdexcept>

#include "gltf_writer.h"
#include "json_types.h"
#include "mesh_builder.h"
#include "model_bounds.h"

namespace make_scenes {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Rounds to 1e-4 so that the scene files read like hand-written ones.
float tidy(float x) {
    const float r = std::round(x * 1e4f) / 1e4f;
    return r == 0.0f ? 0.0f : r;  // no "-0.0"
}

Json vec3(const glm::vec3& v) {
    return Json::array({tidy(v.x), tidy(v.y), tidy(v.z)});
}

// A unit vector from azimuth (degrees, 0 = +X, 90 = +Z) and elevation (degrees above the horizon).
glm::vec3 fromAngles(float azimuthDeg, float elevationDeg) {
    const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
    return {std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)};
}

uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

float hashUnit(uint32_t x) {
    return static_cast<float>(hash32(x) & 0xFFFFu) / 65535.0f;
}

// Sandstone floor tiles: 2 x 2 tiles with grout lines, a shade per tile and a little grain.
TextureImage stoneTiles(const std::string& fileName, uint32_t size) {
    TextureImage t{fileName, size, size, std::vector<uint8_t>(size_t{size} * size * 4)};
    const uint32_t tile = size / 2, grout = std::max(1u, size / 64);
    const glm::vec3 base(206.0f, 186.0f, 154.0f), groutColor(160.0f, 146.0f, 124.0f);
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const uint32_t tx = x / tile, ty = y / tile, lx = x % tile, ly = y % tile;
            const bool inGrout =
                lx < grout || ly < grout || lx >= tile - grout || ly >= tile - grout;
            const float shade = 0.88f + 0.16f * hashUnit(tx * 7u + ty * 13u + 1u);
            const float grain = 0.94f + 0.12f * hashUnit(y * size + x + 101u);
            const glm::vec3 c = inGrout ? groutColor * grain : base * shade * grain;
            uint8_t* px = &t.rgba[(size_t{y} * size + x) * 4];
            for (int k = 0; k < 3; ++k)
                px[k] = static_cast<uint8_t>(std::clamp(std::lround(c[k]), 0L, 255L));
            px[3] = 255;
        }
    }
    return t;
}

Json cameraJson(const glm::vec3& position, const glm::vec3& target, float fovY, float nearP,
                float farP, bool reversedZ, bool infiniteFar) {
    Json c;
    c["position"] = vec3(position);
    c["target"] = vec3(target);
    c["up"] = vec3({0.0f, 1.0f, 0.0f});
    c["fovYDegrees"] = fovY;
    c["near"] = nearP;
    c["far"] = farP;
    c["reversedZ"] = reversedZ;
    c["infiniteFar"] = infiniteFar;
    return c;
}

Json mediumJson(const glm::vec3& betaR, const glm::vec3& betaM, float g, const char* phase,
                float maxDistance) {
    Json m;
    m["betaR"] = Json::array({betaR.x, betaR.y, betaR.z});
    m["betaM"] = Json::array({betaM.x, betaM.y, betaM.z});
    m["g"] = g;
    m["sigmaA"] = Json::array({0.0f, 0.0f, 0.0f});
    m["phase"] = phase;
    m["maxDistance"] = maxDistance;
    return m;
}

// Like dump(2), but arrays of numbers stay on one line: "position": [0.4, 0.5, 3.0].
std::string format(const Json& j, int indent) {
    const std::string pad(static_cast<size_t>(indent), ' '),
        inner(static_cast<size_t>(indent) + 2, ' ');
    if (j.is_object()) {
        std::string out = "{\n";
        size_t i = 0;
        for (const auto& [key, value] : j.items()) {
            out += inner + Json(key).dump() + ": " + format(value, indent + 2);
            out += ++i < j.size() ? ",\n" : "\n";
        }
        return out + pad + "}";
    }
    if (j.is_array()) {
        if (std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_primitive(); })) {
            std::string out = "[";
            for (size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
            return out + "]";
        }
        std::string out = "[\n";
        for (size_t i = 0; i < j.size(); ++i)
            out += inner + format(j[i], indent + 2) + (i + 1 < j.size() ? ",\n" : "\n");
        return out + pad + "]";
    }
    return j.dump();
}

void writeSceneFile(const std::filesystem::path& folder, const std::string& name,
                    const Json& scene) {
    const std::filesystem::path path = folder / (name + ".json");
    std::ofstream out(path, std::ios::trunc);
    out << format(scene, 0) << "\n";
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

// ---------------------------------------------------------------------------------------------
// atrium: a cloister. A court under a slatted roof, arcades on three sides, covered walks behind
// them closed by outer walls. A low sun in the south (+Z) shines through the south wall's windows;
// each beam crosses the walk and falls through an arch into the court, towards the camera.
// Everything is kept compact: a directional light's shadow map covers the scene's bounds.

constexpr float kColumnPitch = 4.0f;
constexpr float kCapitalTop = 5.0f, kArchInner = 1.5f, kArchOuter = 2.0f, kCorniceBottom = 7.4f,
                kCorniceTop = 8.0f;

// An arcade along x at depth z: `columns` columns from x = -(columns - 1) * pitch / 2, arches
// between them, a cornice on top. `endColumns`: whether the first and last columns are drawn (an
// arcade meeting another at a corner shares its corner columns).
void arcade(MeshBuilder& m, float z, int columns, bool endColumns, int stone, int trim) {
    const float x0 = -0.5f * kColumnPitch * static_cast<float>(columns - 1);
    for (int i = 0; i < columns; ++i) {
        const float x = x0 + kColumnPitch * static_cast<float>(i);
        if (endColumns || (i > 0 && i + 1 < columns)) {
            m.use(trim);
            m.box({x, 0.2f, z}, {0.5f, 0.2f, 0.5f});                // plinth
            m.box({x, kCapitalTop - 0.2f, z}, {0.5f, 0.2f, 0.5f});  // capital
            m.box({x, kCapitalTop - 0.47f, z}, {0.4f, 0.07f, 0.4f});
            m.use(stone);
            m.cylinder({x, 0.4f, z}, 0.32f, kCapitalTop - 0.4f - 0.54f, 20);
        }
        if (i + 1 == columns) break;

        // The arch: nine voussoirs on a semicircle, then the spandrel wall up to the cornice.
        const float xm = x + 0.5f * kColumnPitch;
        const int segments = 9;
        const float halfAngle = 0.5f * kPi / static_cast<float>(segments);
        m.use(trim);
        for (int k = 0; k < segments; ++k) {
            const float th = kPi * (static_cast<float>(k) + 0.5f) / static_cast<float>(segments);
            const glm::vec3 radial(std::cos(th), std::sin(th), 0.0f);
            const glm::vec3 tangent(std::sin(th), -std::cos(th), 0.0f);
            const glm::mat3 rot(tangent, radial, glm::vec3(0.0f, 0.0f, 1.0f));
            const float rMid = 0.5f * (kArchInner + kArchOuter);
            m.box(glm::vec3(xm, kCapitalTop, z) + radial * rMid,
                  {kArchOuter * std::sin(halfAngle), 0.5f * (kArchOuter - kArchInner), 0.45f}, rot);
        }
        m.use(stone);
        std::vector<float> xs{xm - 0.5f * kColumnPitch}, bottom{kCapitalTop}, top{kCorniceBottom};
        const float rs = kArchOuter - 0.1f;  // tucked under the voussoirs: no light leaks
        for (int k = 0; k <= 18; ++k) {
            const float phi = kPi * (1.0f - static_cast<float>(k) / 18.0f);
            xs.push_back(xm + rs * std::cos(phi));
            bottom.push_back(kCapitalTop + rs * std::sin(phi));
            top.push_back(kCorniceBottom);
        }
        xs.push_back(xm + 0.5f * kColumnPitch);
        bottom.push_back(kCapitalTop);
        top.push_back(kCorniceBottom);
        m.curtain(xs, bottom, top, z - 0.35f, z + 0.35f);
    }
    m.use(trim);
    const float ends = -x0 + 0.6f;
    m.boxMinMax({-ends, kCorniceBottom, z - 0.55f}, {ends, kCorniceTop, z + 0.55f});
}

// A wall along x from x0 to x1 (z in [z0, z1], up to `height`) with 1.6 m x 4 m windows centred
// at `windows`, each split by an iron mullion.
void windowedWall(MeshBuilder& m, float x0, float x1, float z0, float z1, float height,
                  const std::vector<float>& windows, int mullion) {
    const float half = 0.8f, sill = 1.0f, head = 5.0f;
    const int wall = m.current();
    m.boxMinMax({x0, 0.0f, z0}, {x1, sill, z1});
    m.boxMinMax({x0, head, z0}, {x1, height, z1});
    float from = x0;
    for (float c : windows) {
        m.boxMinMax({from, sill, z0}, {c - half, head, z1});
        from = c + half;
    }
    m.boxMinMax({from, sill, z0}, {x1, head, z1});
    m.use(mullion);
    const float zm = 0.5f * (z0 + z1);
    for (float c : windows)
        m.boxMinMax({c - 0.05f, sill, zm - 0.06f}, {c + 0.05f, head, zm + 0.06f});
    m.use(wall);
}

}  // namespace

SceneSummary writeAtrium(const std::filesystem::path& folder) {
    MeshBuilder m;
    const int tiles = m.addTexture(stoneTiles("atrium_floor.png", 128));
    const int floor = m.addMaterial({"floor_tiles", {1.0f, 1.0f, 1.0f, 1.0f}, tiles}, 1.0f);
    const int stone = m.addMaterial({"sandstone", {0.60f, 0.49f, 0.36f, 1.0f}});
    const int trim = m.addMaterial({"limestone", {0.70f, 0.63f, 0.52f, 1.0f}});
    const int wood = m.addMaterial({"roof_wood", {0.30f, 0.20f, 0.12f, 1.0f}});
    const int plaster = m.addMaterial({"plaster", {0.72f, 0.56f, 0.42f, 1.0f}});
    const int water = m.addMaterial({"water", {0.03f, 0.05f, 0.06f, 1.0f}, -1, 0.05f});
    const int mullion = m.addMaterial({"window_iron", {0.06f, 0.05f, 0.05f, 1.0f}, -1, 0.5f, 1.0f});

    m.use(floor);
    m.boxMinMax({-17.0f, -0.3f, -13.0f}, {20.0f, 0.0f, 16.0f});

    arcade(m, 6.0f, 7, true, stone, trim);   // south, towards the sun: x = -12 .. 12
    arcade(m, -6.0f, 7, true, stone, trim);  // north, in front of the covered walk
    // East, across the end of the court (x = 12, z = -6 .. 6), sharing the corner columns.
    m.place(glm::rotate(glm::mat4(1.0f), 0.5f * kPi, glm::vec3(0.0f, 1.0f, 0.0f)));
    arcade(m, 12.0f, 4, false, stone, trim);
    m.place(glm::mat4(1.0f));

    // The roof: rafters across the court on the cornices, open slats along it on the rafters.
    m.use(wood);
    for (int i = 0; i < 8; ++i) {
        const float x = i == 0 ? -13.35f : -12.0f + kColumnPitch * static_cast<float>(i - 1);
        m.boxMinMax({x - 0.15f, kCorniceTop, -6.6f}, {x + 0.15f, kCorniceTop + 0.35f, 6.6f});
    }
    for (int i = 0; i <= 20; ++i) {
        const float z = -6.0f + 0.6f * static_cast<float>(i);
        m.boxMinMax({-13.5f, kCorniceTop + 0.35f, z - 0.1f},
                    {12.6f, kCorniceTop + 0.49f, z + 0.1f});
    }

    // The covered walks behind the arcades, under solid roofs, closed by outer walls whose windows
    // let the sun in: each beam crosses a walk and falls through an arch into the court.
    const float wallTop = kCorniceTop + 0.4f;
    m.use(wood);
    m.boxMinMax({-13.5f, kCorniceTop, 6.55f}, {16.0f, wallTop, 9.5f});    // south walk
    m.boxMinMax({-13.5f, kCorniceTop, -9.5f}, {16.0f, wallTop, -6.55f});  // north walk
    m.boxMinMax({12.55f, kCorniceTop, -6.55f}, {16.0f, wallTop, 6.55f});  // east walk
    m.use(plaster);
    std::vector<float> southWindows;
    for (int i = 0; i < 6; ++i)
        southWindows.push_back(-9.0f + kColumnPitch * static_cast<float>(i));
    windowedWall(m, -14.0f, 16.5f, 9.5f, 10.0f, wallTop, southWindows, mullion);
    windowedWall(m, -14.0f, 16.5f, -10.0f, -9.5f, wallTop, {}, mullion);
    m.place(glm::rotate(glm::mat4(1.0f), 0.5f * kPi, glm::vec3(0.0f, 1.0f, 0.0f)));
    windowedWall(m, -9.5f, 9.5f, 16.0f, 16.5f, wallTop, {-4.0f, 0.0f, 4.0f}, mullion);  // east
    m.place(glm::mat4(1.0f));
    m.boxMinMax({-14.0f, 0.0f, -9.5f}, {-13.5f, wallTop, 9.5f});  // west

    // A fountain in the court: an octagonal basin of eight stones around dark water, a bowl on a
    // stem.
    const glm::vec3 fountain(2.0f, 0.0f, 0.5f);
    const float apothem = 1.6f;
    m.use(trim);
    for (int k = 0; k < 8; ++k) {
        const float a = 2.0f * kPi * static_cast<float>(k) / 8.0f;
        const glm::vec3 out(std::cos(a), 0.0f, std::sin(a));
        const glm::mat3 rot(glm::vec3(-out.z, 0.0f, out.x), glm::vec3(0.0f, 1.0f, 0.0f), out);
        m.box(fountain + out * apothem + glm::vec3(0.0f, 0.28f, 0.0f),
              {apothem * std::tan(kPi / 8.0f) + 0.04f, 0.28f, 0.12f}, rot);
    }
    m.cylinder(fountain, 0.25f, 1.0f, 12);
    m.cylinder(fountain + glm::vec3(0.0f, 1.0f, 0.0f), 0.7f, 0.16f, 16);
    m.cylinder(fountain + glm::vec3(0.0f, 1.16f, 0.0f), 0.1f, 0.35f, 8);
    m.use(water);
    m.cylinder(fountain, apothem - 0.05f, 0.35f, 16);

    writeGltf(m, folder, "atrium");

    const glm::vec3 toSun = fromAngles(70.0f, 25.0f);
    Json s;
    s["gltf"] = "atrium.gltf";
    s["camera"] =
        cameraJson({-6.0f, 1.7f, -4.0f}, {0.0f, 2.6f, 6.0f}, 65.0f, 0.1f, 500.0f, false, false);
    Json light;
    light["type"] = "directional";
    light["direction"] = vec3(-toSun);
    light["intensity"] = Json::array({20.0f, 18.0f, 15.0f});
    light["shadowMapSize"] = 2048;
    s["light"] = light;
    s["medium"] = mediumJson({5.8e-5f, 1.35e-4f, 3.31e-4f}, {0.025f, 0.025f, 0.025f}, 0.7f,
                             "cornette-shanks", 300.0f);
    s["sky"] = {{"color", Json::array({0.35f, 0.5f, 0.8f})}};
    s["ambient"] = Json::array({0.5f, 0.55f, 0.7f});
    s["exposure"] = 0.8f;
    writeSceneFile(folder, "atrium", s);
    return {"atrium", m.triangleCount(),
            "low sun (25 deg) through windows and arches, slatted roof"};
}

// ---------------------------------------------------------------------------------------------
// window_room: a closed room lit only by a spot light outside, through a barred window.

SceneSummary writeWindowRoom(const std::filesystem::path& folder) {
    MeshBuilder m;
    const int boards = m.addMaterial({"floor_boards", {0.42f, 0.28f, 0.17f, 1.0f}});
    const int walls = m.addMaterial({"wall_paint", {0.66f, 0.64f, 0.58f, 1.0f}});
    const int iron = m.addMaterial({"iron_bars", {0.05f, 0.05f, 0.05f, 1.0f}, -1, 0.6f, 1.0f});
    const int wood = m.addMaterial({"furniture", {0.35f, 0.22f, 0.12f, 1.0f}});
    const int ground = m.addMaterial({"yard", {0.25f, 0.24f, 0.22f, 1.0f}});

    // Interior x in [-4, 4], y in [0, 3.2], z in [-5, 5]; walls 0.25 m thick.
    const float w = 0.25f, h = 3.2f;
    m.use(ground);
    m.boxMinMax({-16.0f, -0.3f, -10.0f}, {-4.0f - w, -0.05f, 10.0f});
    m.use(boards);
    m.boxMinMax({-4.0f - w, -0.2f, -5.0f - w}, {4.0f + w, 0.0f, 5.0f + w});
    m.use(walls);
    m.boxMinMax({-4.0f - w, h, -5.0f - w}, {4.0f + w, h + 0.2f, 5.0f + w});  // ceiling
    m.boxMinMax({4.0f, 0.0f, -5.0f - w}, {4.0f + w, h, 5.0f + w});           // east wall
    m.boxMinMax({-4.0f, 0.0f, -5.0f - w}, {4.0f, h, -5.0f});                 // north wall
    m.boxMinMax({-4.0f, 0.0f, 5.0f}, {4.0f, h, 5.0f + w});                   // south wall
    // The west wall, around the window opening z in [-2.5, -0.5], y in [1.0, 2.6].
    const float wz0 = -2.5f, wz1 = -0.5f, wy0 = 1.0f, wy1 = 2.6f;
    m.boxMinMax({-4.0f - w, 0.0f, -5.0f - w}, {-4.0f, h, wz0});
    m.boxMinMax({-4.0f - w, 0.0f, wz1}, {-4.0f, h, 5.0f + w});
    m.boxMinMax({-4.0f - w, 0.0f, wz0}, {-4.0f, wy0, wz1});
    m.boxMinMax({-4.0f - w, wy1, wz0}, {-4.0f, h, wz1});
    // The grille: three upright bars and two cross bars, 6 cm square, in the wall's middle.
    m.use(iron);
    const float bx = -4.0f - 0.5f * w, b = 0.03f;
    for (int i = 1; i <= 3; ++i) {
        const float z = wz0 + (wz1 - wz0) * static_cast<float>(i) / 4.0f;
        m.boxMinMax({bx - b, wy0, z - b}, {bx + b, wy1, z + b});
    }
    for (int i = 1; i <= 2; ++i) {
        const float y = wy0 + (wy1 - wy0) * static_cast<float>(i) / 3.0f;
        m.boxMinMax({bx - b, y - b, wz0}, {bx + b, y + b, wz1});
    }
    // Furniture for the beam to fall on: a table, a bench, crates, a tall cupboard.
    m.use(wood);
    const glm::vec3 table(0.6f, 0.0f, -1.6f);
    m.boxMinMax(table + glm::vec3(-0.8f, 0.72f, -0.45f), table + glm::vec3(0.8f, 0.77f, 0.45f));
    for (float sx : {-1.0f, 1.0f})
        for (float sz : {-1.0f, 1.0f}) {
            const glm::vec3 leg = table + glm::vec3(sx * 0.7f, 0.0f, sz * 0.36f);
            m.boxMinMax(leg + glm::vec3(-0.04f, 0.0f, -0.04f),
                        leg + glm::vec3(0.04f, 0.72f, 0.04f));
        }
    m.boxMinMax({-0.5f, 0.0f, -3.2f}, {1.7f, 0.45f, -2.85f});  // bench
    m.boxMinMax({2.8f, 0.0f, -4.6f}, {3.6f, 0.8f, -3.8f});     // crates
    m.boxMinMax({2.95f, 0.8f, -4.45f}, {3.55f, 1.35f, -3.85f});
    m.boxMinMax({-3.9f, 0.0f, 2.2f}, {-3.3f, 2.2f, 3.6f});  // cupboard

    writeGltf(m, folder, "window_room");

    const glm::vec3 lightPos(-10.0f, 4.2f, -1.0f);
    const glm::vec3 windowCentre(-4.0f, 1.8f, -1.5f);
    Json s;
    s["gltf"] = "window_room.gltf";
    s["camera"] =
        cameraJson({2.5f, 1.4f, 2.5f}, {-2.0f, 1.1f, -2.0f}, 65.0f, 0.05f, 100.0f, true, false);
    Json light;
    light["type"] = "spot";
    light["position"] = vec3(lightPos);
    light["direction"] = vec3(glm::normalize(windowCentre - lightPos));
    light["intensity"] = Json::array({3000.0f, 2500.0f, 1900.0f});
    light["halfAngleDegrees"] = 22.0f;
    light["range"] = 25.0f;
    light["radius"] = 0.05f;
    light["shadowMapSize"] = 2048;
    s["light"] = light;
    s["medium"] =
        mediumJson({0.0f, 0.0f, 0.0f}, {0.08f, 0.08f, 0.08f}, 0.6f, "cornette-shanks", 100.0f);
    s["sky"] = {{"color", Json::array({0.03f, 0.04f, 0.07f})}};
    s["ambient"] = Json::array({0.3f, 0.3f, 0.36f});
    s["exposure"] = 1.5f;
    writeSceneFile(folder, "window_room", s);
    return {"window_room", m.triangleCount(), "spot through a barred window, reversed Z"};
}

// ---------------------------------------------------------------------------------------------
// engine_spot: the Khronos 2CylinderEngine on a floor, back-lit by a spot shining at the camera.

SceneSummary writeEngineSpot(const std::filesystem::path& folder, const std::string& engineGlb) {
    const ModelPoints engine = loadModelPoints(engineGlb);
    const float yaw = 30.0f;
    const glm::mat3 rot(glm::rotate(glm::mat4(1.0f), glm::radians(yaw), {0.0f, 1.0f, 0.0f}));
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : engine.points) {
        lo = glm::min(lo, rot * p);
        hi = glm::max(hi, rot * p);
    }
    const glm::vec3 extent = hi - lo;
    // Four significant digits: the longest side comes out at 2 m to within 0.05%.
    const float raw = 2.0f / std::max({extent.x, extent.y, extent.z});
    const float digits = std::pow(10.0f, 3.0f - std::floor(std::log10(raw)));
    const float scale = std::round(raw * digits) / digits;
    const glm::vec3 centre = 0.5f * (lo + hi) * scale;
    const glm::vec3 translation(-centre.x, -lo.y * scale, -centre.z);  // resting on y = 0

    MeshBuilder m;
    const int concrete = m.addMaterial({"concrete", {0.45f, 0.44f, 0.42f, 1.0f}});
    const int wall = m.addMaterial({"back_wall", {0.35f, 0.36f, 0.38f, 1.0f}});
    m.use(concrete);
    m.boxMinMax({-8.0f, -0.2f, -8.0f}, {8.0f, 0.0f, 9.0f});
    m.use(wall);
    m.boxMinMax({-8.0f, 0.0f, -8.5f}, {8.0f, 6.0f, -8.0f});
    writeGltf(m, folder, "engine_spot");

    const glm::vec3 lightPos(0.0f, 1.0f, -7.2f);  // hidden behind the engine
    const glm::vec3 aim(0.0f, 0.5f, 4.0f);
    Json s;
    s["gltf"] = "engine_spot.gltf";
    Json model;
    model["gltf"] = engineGlb;
    model["translation"] = vec3(translation);
    model["rotationDegrees"] = Json::array({0.0f, yaw, 0.0f});
    model["scale"] = scale;
    s["models"] = Json::array({model});
    s["camera"] =
        cameraJson({0.4f, 0.5f, 3.0f}, {0.0f, 0.8f, -2.0f}, 55.0f, 0.1f, 200.0f, false, false);
    Json light;
    light["type"] = "spot";
    light["position"] = vec3(lightPos);
    light["direction"] = vec3(glm::normalize(aim - lightPos));
    light["intensity"] = Json::array({1000.0f, 1000.0f, 1100.0f});
    light["halfAngleDegrees"] = 16.0f;
    light["range"] = 20.0f;
    light["radius"] = 0.05f;
    light["shadowMapSize"] = 2048;
    s["light"] = light;
    s["medium"] =
        mediumJson({0.0f, 0.0f, 0.0f}, {0.04f, 0.04f, 0.04f}, 0.5f, "cornette-shanks", 200.0f);
    s["sky"] = {{"color", Json::array({0.0f, 0.0f, 0.0f})}};
    s["ambient"] = Json::array({0.15f, 0.15f, 0.17f});
    s["exposure"] = 0.4f;
    writeSceneFile(folder, "engine_spot", s);
    return {"engine_spot", m.triangleCount(),
            "engine " + std::to_string(engine.triangles) + " triangles, scale " +
                std::to_string(scale)};
}

// ---------------------------------------------------------------------------------------------
// point_fog: a lantern-like point light in dense fog, no shadow map, pillars around it.

SceneSummary writePointFog(const std::filesystem::path& folder) {
    MeshBuilder m;
    const int paving = m.addMaterial({"paving", {0.30f, 0.29f, 0.27f, 1.0f}});
    const int stone = m.addMaterial({"pillar_stone", {0.55f, 0.53f, 0.50f, 1.0f}});
    const int dark = m.addMaterial({"weathered_stone", {0.35f, 0.33f, 0.30f, 1.0f}});
    m.use(paving);
    m.boxMinMax({-20.0f, -0.2f, -20.0f}, {20.0f, 0.0f, 20.0f});
    // Eight round pillars on a ring around the light, square ones further out.
    for (int i = 0; i < 8; ++i) {
        const float a = 2.0f * kPi * (static_cast<float>(i) + 0.5f) / 8.0f;
        const glm::vec3 p(4.5f * std::cos(a), 0.0f, 4.5f * std::sin(a));
        m.use(dark);
        m.boxMinMax(p + glm::vec3(-0.45f, 0.0f, -0.45f), p + glm::vec3(0.45f, 0.3f, 0.45f));
        m.use(stone);
        m.cylinder(p + glm::vec3(0.0f, 0.3f, 0.0f), 0.3f, 3.7f, 16);
    }
    m.use(dark);
    for (int i = 0; i < 12; ++i) {
        const float a = 2.0f * kPi * (static_cast<float>(i) + 0.5f) / 12.0f;
        const glm::vec3 p(10.0f * std::cos(a), 0.0f, 10.0f * std::sin(a));
        const float height = 2.0f + 2.5f * hashUnit(static_cast<uint32_t>(i) + 7u);
        m.boxMinMax(p + glm::vec3(-0.4f, 0.0f, -0.4f), p + glm::vec3(0.4f, height, 0.4f));
    }
    // A low basin under the light.
    m.use(stone);
    m.cylinder({0.0f, 0.0f, 0.0f}, 0.9f, 0.5f, 24);
    writeGltf(m, folder, "point_fog");

    Json s;
    s["gltf"] = "point_fog.gltf";
    s["camera"] =
        cameraJson({0.6f, 1.7f, 9.0f}, {0.0f, 1.8f, 0.0f}, 60.0f, 0.1f, 1000.0f, false, true);
    Json light;
    light["type"] = "point";
    light["position"] = vec3({0.0f, 2.2f, 0.0f});
    light["intensity"] = Json::array({150.0f, 120.0f, 85.0f});
    light["radius"] = 0.05f;
    light["shadowMapSize"] = 0;
    s["light"] = light;
    s["medium"] = mediumJson({0.0f, 0.0f, 0.0f}, {0.12f, 0.12f, 0.12f}, 0.0f, "isotropic", 60.0f);
    s["sky"] = {{"color", Json::array({0.004f, 0.006f, 0.012f})}};
    s["ambient"] = Json::array({0.02f, 0.02f, 0.03f});
    s["exposure"] = 0.8f;
    writeSceneFile(folder, "point_fog", s);
    return {"point_fog", m.triangleCount(), "point light, no shadow map, infinite far plane"};
}

// ---------------------------------------------------------------------------------------------
// valley_fog: a valley at sunset under height fog. The valley runs along x between two ridges and
// opens to the west (-x) onto a plain, where the sun sets a few degrees over the horizon. Trees
// and rock pinnacles in the valley's mouth and peaks on the northern ridge stand between the
// camera and the sun: their shadows run up the valley as long shafts through the fog layer.

namespace {

float smoothStep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

struct Peak {
    float x, z, radius, height;
};

// Peaks on the ridges (metres above the ridge line): five on the low northern (+z) ridge, with
// saddles between them, and two on the southern one.
constexpr std::array<Peak, 7> kValleyPeaks{{{-380.0f, 150.0f, 34.0f, 60.0f},
                                            {-265.0f, 160.0f, 30.0f, 75.0f},
                                            {-150.0f, 150.0f, 36.0f, 62.0f},
                                            {-40.0f, 165.0f, 30.0f, 70.0f},
                                            {70.0f, 155.0f, 34.0f, 55.0f},
                                            {-300.0f, -165.0f, 40.0f, 35.0f},
                                            {60.0f, -175.0f, 45.0f, 30.0f}}};

// The valley floor's centre line, metres in z.
float valleyCentre(float x) {
    return 15.0f * std::sin(x / 110.0f + 0.6f);
}

// The terrain: a floor about 60 m wide at y ~ 0 rising to a low northern ridge (about 24 m, the
// sun's side) and a higher southern one (about 75 m), both about 165 m from the floor's centre
// line, and falling away behind them. West of x = -450 the ridges sink into a plain.
float valleyHeight(float x, float z) {
    const float u = std::fabs(z - valleyCentre(x));
    const bool north = z > valleyCentre(x);
    const float side = north ? 1.0f : -1.0f;
    const float crest = (north ? 24.0f : 75.0f) + 6.0f * std::sin(x / 70.0f + 1.3f * side) +
                        4.0f * std::sin(x / 23.0f + 2.1f * side);
    const float crestAt = 165.0f;
    const float ridge = u < crestAt ? crest * smoothStep(30.0f, crestAt, u)
                                    : std::max(crest - 0.35f * (u - crestAt), 0.45f * crest);
    const float open = smoothStep(-680.0f, -450.0f, x);  // 0 on the western plain
    float h = open * ridge;
    for (const Peak& p : kValleyPeaks) {
        const float d2 = (x - p.x) * (x - p.x) + (z - p.z) * (z - p.z);
        h += open * p.height * std::exp(-d2 / (p.radius * p.radius));
    }
    // Gentle undulation everywhere (the floor is not a plane), rougher higher up.
    h += 0.9f * std::sin(x / 9.0f) * std::sin(z / 11.0f) + 2.0f * std::sin(x / 41.0f + z / 37.0f);
    h += std::clamp(h / 60.0f, 0.0f, 1.5f) * 4.0f * std::sin(x / 13.0f + z / 17.0f) *
         std::sin(z / 19.0f - x / 29.0f);
    return h;
}

// A conifer standing on the terrain at (x, z): a trunk and two stacked cones.
void conifer(MeshBuilder& m, float x, float z, float height, int bark, int needles) {
    const glm::vec3 base(x, valleyHeight(x, z) - 0.5f, z);
    m.use(bark);
    m.cylinder(base, 0.045f * height, 0.35f * height + 0.5f, 6);
    m.use(needles);
    m.cone(base + glm::vec3(0.0f, 0.22f * height, 0.0f), 0.24f * height, 0.5f * height, 8);
    m.cone(base + glm::vec3(0.0f, 0.5f * height, 0.0f), 0.17f * height, 0.5f * height + 0.5f, 8);
}

}  // namespace

SceneSummary writeValleyFog(const std::filesystem::path& folder) {
    MeshBuilder m;
    const int grass = m.addMaterial({"valley_grass", {0.22f, 0.25f, 0.13f, 1.0f}});
    const int rock = m.addMaterial({"rock", {0.38f, 0.34f, 0.30f, 1.0f}});
    const int bark = m.addMaterial({"bark", {0.20f, 0.13f, 0.08f, 1.0f}});
    const int needles = m.addMaterial({"needles", {0.07f, 0.13f, 0.07f, 1.0f}});

    m.use(grass);
    m.heightfield({-700.0f, -300.0f}, {300.0f, 300.0f}, 200, 120, valleyHeight);

    // A wood on the northern slope, against the sun, and a few trees on the valley floor.
    for (uint32_t i = 0; i < 110; ++i) {
        const float x = -450.0f + 600.0f * hashUnit(3u * i + 11u);
        const float z = valleyCentre(x) + 50.0f + 100.0f * hashUnit(3u * i + 12u);
        const float height = 10.0f + 10.0f * hashUnit(3u * i + 13u);
        conifer(m, x, z, height, bark, needles);
    }
    for (uint32_t i = 0; i < 24; ++i) {
        const float x = -350.0f + 450.0f * hashUnit(3u * i + 511u);
        const float z = valleyCentre(x) - 40.0f + 110.0f * hashUnit(3u * i + 512u);
        const float height = 8.0f + 8.0f * hashUnit(3u * i + 513u);
        conifer(m, x, z, height, bark, needles);
    }
    // Rock pinnacles (x, z, half width, height) on the northern slope, turned about the vertical
    // and leaning a little.
    m.use(rock);
    const std::array<glm::vec4, 5> pinnacles{{{-330.0f, 105.0f, 4.5f, 34.0f},
                                              {-215.0f, 120.0f, 3.5f, 26.0f},
                                              {-95.0f, 100.0f, 5.0f, 40.0f},
                                              {15.0f, 115.0f, 3.0f, 24.0f},
                                              {110.0f, 110.0f, 4.0f, 30.0f}}};
    for (size_t i = 0; i < pinnacles.size(); ++i) {
        const glm::vec4& p = pinnacles[i];
        const float yaw = 2.0f * kPi * hashUnit(static_cast<uint32_t>(i) + 90u);
        const float lean = glm::radians(6.0f * (hashUnit(static_cast<uint32_t>(i) + 95u) - 0.5f));
        const glm::mat3 rot(glm::rotate(glm::rotate(glm::mat4(1.0f), yaw, {0.0f, 1.0f, 0.0f}), lean,
                                        {1.0f, 0.0f, 0.0f}));
        const float y = valleyHeight(p.x, p.y) - 2.0f;
        m.box({p.x, y + 0.5f * p.w, p.y}, {p.z, 0.5f * p.w, 0.7f * p.z}, rot);
        m.box({p.x, y + p.w + 0.25f * p.z, p.y}, {0.7f * p.z, 0.25f * p.z + 0.5f, 0.5f * p.z}, rot);
    }
    writeGltf(m, folder, "valley_fog");

    // The sun sets in the north-west, 5 degrees up, behind a saddle of the northern ridge as the
    // camera on the southern slope sees it.
    const glm::vec3 toSun = fromAngles(150.0f, 5.0f);
    const glm::vec3 eye(175.0f, valleyHeight(175.0f, -80.0f) + 3.0f, -80.0f);
    Json s;
    s["gltf"] = "valley_fog.gltf";
    s["camera"] = cameraJson(eye, {-200.0f, 15.0f, 200.0f}, 50.0f, 0.5f, 3000.0f, false, false);
    Json light;
    light["type"] = "directional";
    light["direction"] = vec3(-toSun);
    light["intensity"] = Json::array({16.0f, 9.5f, 4.5f});
    light["shadowMapSize"] = 2048;
    s["light"] = light;
    Json medium = mediumJson({5.8e-6f, 1.35e-5f, 3.31e-5f}, {0.006f, 0.006f, 0.006f}, 0.6f,
                             "cornette-shanks", 3000.0f);
    medium["density"] = 1.0f;
    medium["heightFog"] = {{"baseHeight", 10.0f}, {"falloff", 0.05f}};
    s["medium"] = medium;
    s["sky"] = {{"color", Json::array({0.3f, 0.29f, 0.38f})}};
    s["ambient"] = Json::array({0.16f, 0.15f, 0.2f});
    s["exposure"] = 0.55f;
    writeSceneFile(folder, "valley_fog", s);
    return {"valley_fog", m.triangleCount(), "sun 5 deg behind a ridge's saddle, height fog"};
}

}  // namespace make_scenes
