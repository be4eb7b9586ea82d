// Embree 3 as a benchmark peer: one triangle geometry, the default build quality and flags, as a
// renderer sets it up; rtcIntersect1 and rtcIntersect16 with the ray from t = 0 to infinity.
#include "embree_peer.hpp"

#include <embree3/rtcore.h>
#include <limits>
#include <stdexcept>

namespace embree_peer {

scene::scene(const double* xyz, std::size_t vertices, const std::uint32_t* triangles, std::size_t count) {
    RTCDevice device = rtcNewDevice(nullptr);
    if (device == nullptr) throw std::runtime_error("rtcNewDevice failed");
    RTCScene s = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices));
    for (std::size_t i = 0; i < 3 * vertices; ++i) v[i] = static_cast<float>(xyz[i]);
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    for (std::size_t i = 0; i < 3 * count; ++i) t[i] = triangles[i];
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    device_ = device;
    scene_ = s;
}

scene::~scene() {
    rtcReleaseScene(static_cast<RTCScene>(scene_));
    rtcReleaseDevice(static_cast<RTCDevice>(device_));
}

hit scene::intersect1(const double o[3], const double d[3]) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit r{};
    r.ray.org_x = static_cast<float>(o[0]);
    r.ray.org_y = static_cast<float>(o[1]);
    r.ray.org_z = static_cast<float>(o[2]);
    r.ray.dir_x = static_cast<float>(d[0]);
    r.ray.dir_y = static_cast<float>(d[1]);
    r.ray.dir_z = static_cast<float>(d[2]);
    r.ray.tnear = 0.0f;
    r.ray.tfar = std::numeric_limits<float>::infinity();
    r.ray.mask = 0xffffffffu;
    r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene_), &context, &r);
    return {r.ray.tfar, r.hit.primID, r.hit.geomID != RTC_INVALID_GEOMETRY_ID};
}

void scene::intersect16(const double* o, const double* d, hit* out) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(64) RTCRayHit16 r{};
    alignas(64) int valid[16];
    for (int i = 0; i < 16; ++i) {
        valid[i] = -1;
        r.ray.org_x[i] = static_cast<float>(o[3 * i]);
        r.ray.org_y[i] = static_cast<float>(o[3 * i + 1]);
        r.ray.org_z[i] = static_cast<float>(o[3 * i + 2]);
        r.ray.dir_x[i] = static_cast<float>(d[3 * i]);
        r.ray.dir_y[i] = static_cast<float>(d[3 * i + 1]);
        r.ray.dir_z[i] = static_cast<float>(d[3 * i + 2]);
        r.ray.tnear[i] = 0.0f;
        r.ray.tfar[i] = std::numeric_limits<float>::infinity();
        r.ray.mask[i] = 0xffffffffu;
        r.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, static_cast<RTCScene>(scene_), &context, &r);
    for (int i = 0; i < 16; ++i) out[i] = {r.ray.tfar[i], r.hit.primID[i], r.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID};
}

} // namespace embree_peer
