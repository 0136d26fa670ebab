#include "scattering_params.h"

#include <algorithm>
#include <cmath>

#include "medium_constants.h"

namespace ls {

TableLayout tableLayoutFor(const MediumParams& medium, float lightRadius, uint32_t width,
                           uint32_t height) {
    // A non-uniform medium's table has no extinction (point_table.comp).
    const glm::vec3 bt = medium.nonUniform() ? glm::vec3(0.0f) : medium.betaT();
    // The table changes with h on two scales: near r0, where the phase angle along the ray turns
    // from a step into a smooth sweep, and near 1/betaT, where extinction sets in. A log axis
    // resolves both; past 50 extinction lengths (or the sky distance without extinction) nothing
    // is left to resolve.
    const float minBeta = std::min({bt.x, bt.y, bt.z});
    const float scale =
        std::max(minBeta > 0.0f ? 50.0f / minBeta : 0.0f, 10.0f * medium.maxDistance);
    TableLayout t;
    t.width = width;
    t.height = height;
    const float r0 = std::max(lightRadius, 1e-6f);
    t.logRange = std::max(std::log(std::max(scale, r0) / r0), 1.0f);
    return t;
}

float MediumParams::maxDensity() const {
    float m = density;
    for (const FogVolumeParams& v : volumes) m += v.density;
    return m;
}

LightOnScreen projectLight(const CameraParams& camera, const LightParams& light) {
    const glm::mat4 viewProj = camera.projection * camera.view;
    const glm::vec4 clip = light.kind == LightType::Directional
                               ? viewProj * glm::vec4(-light.direction, 0.0f)
                               : viewProj * glm::vec4(light.position, 1.0f);
    LightOnScreen s;
    s.wSign = clip.w < 0.0f ? -1.0f : 1.0f;
    // A light in the camera's plane projects to infinity: keep its direction at a finite distance.
    const float w = std::max(std::fabs(clip.w), 1e-6f) * s.wSign;
    glm::vec2 ndc = glm::vec2(clip) / w;
    const float len = glm::length(ndc);
    if (len > 1e6f) ndc *= 1e6f / len;
    s.ndc = ndc;
    s.onScreen = s.wSign > 0.0f && std::fabs(ndc.x) <= 1.0f && std::fabs(ndc.y) <= 1.0f;
    return s;
}

const char* cubeFaceName(int face) {
    static const char* const kNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    return face >= 0 && face < 6 ? kNames[face] : "?";
}

namespace {

// The view-space direction D (w = 0) that lands at NDC (x, y) has clip x = x clip w and clip
// y = y clip w: it is orthogonal to the xyz of rows 0 - x row 3 and 1 - y row 3 of the projection,
// so D = r0 x r1 + x (r1 x r3) + y (r3 x r0), linear in x and y, whatever the near plane.
// Unprojecting a point at some depth and subtracting the camera's position instead cancels: at near
// 1e-8 m the point lies 2e-8 m from a camera whose coordinates' float32 step is 1e-6 m. In double,
// scaled so that the centre's vector is a unit one pointing ahead (clip w > 0), turned into the
// world by the view's rotation.
glm::mat4 rayBasisOf(const glm::mat4& projection, const glm::mat4& view) {
    const glm::dmat4 p(projection);
    auto row = [&](int r) { return glm::dvec3(p[0][r], p[1][r], p[2][r]); };
    const glm::dvec3 r0 = row(0), r1 = row(1), r3 = row(3);
    const glm::dvec3 x = glm::cross(r1, r3), y = glm::cross(r3, r0), centre = glm::cross(r0, r1);
    double scale = glm::length(centre);
    if (!(scale > 0.0)) return glm::mat4(0.0f);  // not a perspective projection (refused before)
    if (glm::dot(r3, centre) < 0.0) scale = -scale;
    const glm::dmat3 toWorld = glm::inverse(glm::dmat3(glm::dmat4(view)));
    glm::mat4 basis(0.0f);
    basis[0] = glm::vec4(glm::vec3(toWorld * (x / scale)), 0.0f);
    basis[1] = glm::vec4(glm::vec3(toWorld * (y / scale)), 0.0f);
    basis[2] = glm::vec4(glm::vec3(toWorld * (centre / scale)), 0.0f);
    return basis;
}

}  // namespace

FrameConstants makeFrameConstants(const CameraParams& camera, const LightParams& light,
                                  const MediumParams& medium, const FrameParams& params,
                                  const TableLayout& table) {
    const VkExtent2D screen = params.screen;
    FrameConstants f{};
    f.viewProj = camera.projection * camera.view;
    f.viewProjFromCamera = camera.projection * glm::mat4(glm::mat3(camera.view));
    f.rayBasis = rayBasisOf(camera.projection, camera.view);
    f.lightViewProj = light.shadowViewProj;
    for (int i = 0; i < 6; ++i) f.cubeFaceViewProj[i] = light.cubeFaceViewProj[i];
    const glm::mat4 invView = glm::inverse(camera.view);
    f.cameraPos = glm::vec4(glm::vec3(invView[3]), camera.nearPlane);
    f.cameraForward = glm::vec4(-glm::normalize(glm::vec3(invView[2])), camera.farPlane);
    f.screenSize = {static_cast<float>(screen.width), static_cast<float>(screen.height),
                    1.0f / static_cast<float>(screen.width),
                    1.0f / static_cast<float>(screen.height)};
    f.lightPos = glm::vec4(light.position, 0.0f);
    f.lightDir = glm::vec4(glm::normalize(light.direction), light.cosOuter);
    f.lightIntensity = glm::vec4(light.intensity, light.range);
    // 1 / (cos inner - cos outer), 0 for a hard edge (no division: a step).
    const float penumbra = light.cosInner - light.cosOuter;
    f.lightFalloff = {light.cosInner, penumbra > 0.0f ? 1.0f / penumbra : 0.0f,
                      light.windowedRange ? 1.0f : 0.0f,
                      std::acos(std::clamp(light.cosOuter, -1.0f, 1.0f)) -
                          std::acos(std::clamp(light.cosInner, -1.0f, 1.0f))};
    const LightOnScreen ls = projectLight(camera, light);
    f.lightScreen = {ls.ndc.x, ls.ndc.y, ls.wSign, ls.onScreen ? 1.0f : 0.0f};
    f.betaR = glm::vec4(medium.betaR, medium.g);
    f.betaM = glm::vec4(medium.betaM, medium.maxDistance);
    f.betaT = glm::vec4(medium.betaT(), std::max(light.radius, 1e-6f));
    f.depthInfo = {camera.reversedZ ? 1.0f : 0.0f, camera.infiniteFar ? 1.0f : 0.0f,
                   camera.nearPlane, camera.farPlane};
    const float size = static_cast<float>(
        std::max(light.shadowMapSize > 0 ? light.shadowMapSize : light.lightColorSize, 1u));
    f.shadowInfo = {size, 1.0f / size, light.shadowReversedZ ? 1.0f : 0.0f, light.shadowDepthBias};
    f.lutInfo = {table.logRange, static_cast<float>(table.width), static_cast<float>(table.height),
                 0.0f};
    // Seed 004's I / (a1 r^2 + a0) as (I / a1) / (r^2 + a0 / a1); the floor keeps a ray through
    // the light finite when a0 is 0, as the floor on r0 does for the full model; the ceilings
    // keep a denormal a1 from making them infinite.
    const float a1 = params.simplifiedA1;
    f.simplified = {std::clamp(params.simplifiedA0 / a1, 1e-12f, 1e30f), std::min(1.0f / a1, 1e30f),
                    0.0f, 0.0f};
    const VkExtent2D texels = params.maxScreen.width != 0 ? params.maxScreen : screen;
    f.screenTexels = {static_cast<float>(texels.width), static_cast<float>(texels.height),
                      static_cast<float>(screen.width) / static_cast<float>(texels.width),
                      static_cast<float>(screen.height) / static_cast<float>(texels.height)};
    f.linStorage = {params.linStorage, 1.0f / params.linStorage, params.preExposure, 0.0f};
    if (medium.nonUniform()) writeMediumConstants(f, camera, light, medium);
    return f;
}

}  // namespace ls
