#include "embree_occlusion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>

#include <embree3/rtcore.h>

namespace host::reference {
namespace {

// One Embree device for the process: creating one starts its task system, too slow to repeat for
// every scene a test builds. It is never released (the process's end does).
RTCDevice sharedDevice() {
    static std::once_flag once;
    static RTCDevice device = nullptr;
    std::call_once(once, [] {
        device = rtcNewDevice(nullptr);
        if (device == nullptr) {
            std::fprintf(stderr,
                         "reference renderer: Embree refused to start (error %d); the double BVH "
                         "answers every query\n",
                         static_cast<int>(rtcGetDeviceError(nullptr)));
        }
    });
    return device;
}

// Embree's context, extended with the double queries that the candidates are tested against
// (Embree passes the context it was given to the callbacks; each Embree ray's id is its query's
// index).
struct QueryContext {
    RTCIntersectContext embree;
    const OcclusionQuery* queries;
    const std::vector<Triangle>* triangles;
};

float roundDown(double v) {
    const auto f = static_cast<float>(v);
    return static_cast<double>(f) <= v ? f : std::nextafter(f, -std::numeric_limits<float>::max());
}
float roundUp(double v) {
    const auto f = static_cast<float>(v);
    return static_cast<double>(f) >= v ? f : std::nextafter(f, std::numeric_limits<float>::max());
}

class EmbreeScene final : public EmbreeOcclusion {
  public:
    EmbreeScene(RTCDevice device, const std::vector<Triangle>& triangles, double scale)
        : triangles_(triangles), padding_(kPadding * scale), reach_(kReach * scale) {
        scene_ = rtcNewScene(device);
        rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(triangles_.size()));
        rtcSetGeometryUserData(geometry, this);
        rtcSetGeometryBoundsFunction(geometry, &EmbreeScene::bounds, this);
        rtcSetGeometryOccludedFunction(geometry, &EmbreeScene::occluded);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene_);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;
    ~EmbreeScene() override { rtcReleaseScene(scene_); }

    [[nodiscard]] bool ok(RTCDevice device) const {
        return rtcGetDeviceError(device) == RTC_ERROR_NONE;
    }

    std::optional<bool> anyHit(const PreparedRay& ray, double tMin, double tMax) const override {
        const OcclusionQuery query{ray, tMin, tMax};
        if (!covers(query)) return std::nullopt;
        QueryContext context = makeContext(&query, RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
        RTCRay r = embreeRay(query, 0);
        rtcOccluded1(scene_, &context.embree, &r);
        return r.tfar < 0.0f;  // Embree's mark of an occluded ray: -inf
    }

    void anyHit(std::span<const OcclusionQuery> queries, std::span<uint8_t> hits) const override {
        thread_local std::vector<RTCRay> rays;
        rays.clear();
        for (std::size_t i = 0; i < queries.size(); ++i)
            if (covers(queries[i])) rays.push_back(embreeRay(queries[i], static_cast<unsigned>(i)));
        if (rays.empty()) return;
        QueryContext context = makeContext(queries.data(), RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
        rtcOccluded1M(scene_, &context.embree, rays.data(), static_cast<unsigned>(rays.size()),
                      sizeof(RTCRay));
        for (const RTCRay& r : rays) hits[r.id] = r.tfar < 0.0f ? 1 : 0;
    }

  private:
    // Whether the padding covers the float rounding of this query's ray over the scene's boxes:
    // the origin within kReach scales, a unit-scale direction (LightVisibility's are unit).
    [[nodiscard]] bool covers(const OcclusionQuery& q) const {
        const glm::dvec3& o = q.ray.origin;
        const glm::dvec3& d = q.ray.direction;
        const double oMax = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
        const double dMax = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        return oMax <= reach_ && dMax <= 2.0 && dMax >= 0.5 && q.tMin >= 0.0 && q.tMax >= q.tMin;
    }

    [[nodiscard]] QueryContext makeContext(const OcclusionQuery* queries,
                                           RTCIntersectContextFlags flags) const {
        QueryContext context{{}, queries, &triangles_};
        rtcInitIntersectContext(&context.embree);
        context.embree.flags = flags;
        return context;
    }

    [[nodiscard]] RTCRay embreeRay(const OcclusionQuery& q, unsigned id) const {
        RTCRay r{};
        r.org_x = static_cast<float>(q.ray.origin.x);
        r.org_y = static_cast<float>(q.ray.origin.y);
        r.org_z = static_cast<float>(q.ray.origin.z);
        r.dir_x = static_cast<float>(q.ray.direction.x);
        r.dir_y = static_cast<float>(q.ray.direction.y);
        r.dir_z = static_cast<float>(q.ray.direction.z);
        // Boxes are entered a little before the double ray's hit; intersectTriangle keeps to
        // [tMin, tMax] itself.
        r.tnear = 0.0f;
        r.tfar = std::isinf(q.tMax) ? std::numeric_limits<float>::infinity()
                                    : roundUp(q.tMax + padding_ * 4.0);
        r.mask = 0xFFFFFFFFu;
        r.id = id;
        return r;
    }

    static void bounds(const RTCBoundsFunctionArguments* args) {
        const auto* self = static_cast<const EmbreeScene*>(args->geometryUserPtr);
        const Triangle& t = self->triangles_[args->primID];
        const glm::dvec3 lo = glm::min(glm::min(t.a, t.b), t.c) - self->padding_;
        const glm::dvec3 hi = glm::max(glm::max(t.a, t.b), t.c) + self->padding_;
        RTCBounds* b = args->bounds_o;
        b->lower_x = roundDown(lo.x);
        b->lower_y = roundDown(lo.y);
        b->lower_z = roundDown(lo.z);
        b->upper_x = roundUp(hi.x);
        b->upper_y = roundUp(hi.y);
        b->upper_z = roundUp(hi.z);
    }

    static void occluded(const RTCOccludedFunctionNArguments* args) {
        const auto* context = reinterpret_cast<const QueryContext*>(args->context);
        for (unsigned i = 0; i < args->N; ++i) {
            if (args->valid[i] != -1) continue;
            const OcclusionQuery& q = context->queries[RTCRayN_id(args->ray, args->N, i)];
            if (intersectTriangle(q.ray, (*context->triangles)[args->primID], q.tMin, q.tMax))
                RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
        }
    }

    std::vector<Triangle> triangles_;
    double padding_, reach_;
    RTCScene scene_ = nullptr;
};

}  // namespace

std::shared_ptr<const EmbreeOcclusion> makeEmbreeOcclusion(const std::vector<Triangle>& triangles,
                                                           double coordinateScale) {
    RTCDevice device = sharedDevice();
    if (device == nullptr || triangles.empty() || !(coordinateScale > 0.0) ||
        !std::isfinite(coordinateScale))
        return nullptr;
    // A non-finite vertex has no box to pad; the double BVH handles it as its tests expect.
    for (const Triangle& t : triangles)
        for (const glm::dvec3& p : {t.a, t.b, t.c})
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return nullptr;
    auto scene = std::make_shared<EmbreeScene>(device, triangles, coordinateScale);
    if (!scene->ok(device)) return nullptr;
    return scene;
}

}  // namespace host::reference
