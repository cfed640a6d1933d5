#include "lab/sim/ray_caster.h"

#include <embree3/rtcore.h>
#include <glog/logging.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace mlndt {
namespace sim {

struct RayCaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<Eigen::Vector3d> normals;  // Per triangle.
};

namespace {

std::string EmbreeError(RTCDevice device, const std::string& what) {
  return "embree: " + what + " failed (error code " +
         std::to_string(static_cast<int>(rtcGetDeviceError(device))) + ")";
}

bool CheckMesh(const TriangleMesh& mesh, std::string* error) {
  if (mesh.empty()) {
    *error = "ray caster: the mesh has no triangles";
    return false;
  }
  for (const Eigen::Vector3f& v : mesh.vertices) {
    if (!v.allFinite()) {
      *error = "ray caster: a vertex is not finite";
      return false;
    }
  }
  for (const auto& tri : mesh.triangles) {
    for (const uint32_t index : tri) {
      if (index >= mesh.vertices.size()) {
        *error = "ray caster: a triangle's vertex index is out of range";
        return false;
      }
    }
  }
  return true;
}

}  // namespace

std::unique_ptr<RayCaster> RayCaster::Create(const TriangleMesh& mesh,
                                             std::string* error) {
  CHECK(error != nullptr);
  if (!CheckMesh(mesh, error)) return nullptr;
  std::unique_ptr<RayCaster> caster(new RayCaster());
  caster->impl_ = std::make_unique<Impl>();
  Impl& impl = *caster->impl_;
  impl.device = rtcNewDevice("threads=1,set_affinity=0,verbose=0");
  if (impl.device == nullptr) {
    *error = EmbreeError(nullptr, "rtcNewDevice");
    return nullptr;
  }
  RTCGeometry geometry =
      rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices =
      static_cast<float*>(rtcSetNewGeometryBuffer(geometry,
                                                  RTC_BUFFER_TYPE_VERTEX,
                                                  0,
                                                  RTC_FORMAT_FLOAT3,
                                                  3 * sizeof(float),
                                                  mesh.vertices.size()));
  auto* indices =
      static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry,
                                                     RTC_BUFFER_TYPE_INDEX,
                                                     0,
                                                     RTC_FORMAT_UINT3,
                                                     3 * sizeof(uint32_t),
                                                     mesh.triangles.size()));
  if (vertices == nullptr || indices == nullptr) {
    *error = EmbreeError(impl.device, "rtcSetNewGeometryBuffer");
    rtcReleaseGeometry(geometry);
    return nullptr;
  }
  for (size_t k = 0; k < mesh.vertices.size(); ++k) {
    std::memcpy(vertices + 3 * k, mesh.vertices[k].data(), 3 * sizeof(float));
  }
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    std::memcpy(
        indices + 3 * k, mesh.triangles[k].data(), 3 * sizeof(uint32_t));
  }
  rtcSetGeometryMask(geometry, 0xFFFFFFFFu);
  rtcCommitGeometry(geometry);
  impl.scene = rtcNewScene(impl.device);
  rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_ROBUST);
  rtcAttachGeometry(impl.scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(impl.scene);
  if (rtcGetDeviceError(impl.device) != RTC_ERROR_NONE) {
    *error = EmbreeError(impl.device, "building the scene");
    return nullptr;
  }
  impl.normals.reserve(mesh.triangles.size());
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    impl.normals.push_back(TriangleNormal(mesh, k));
  }
  return caster;
}

RayCaster::~RayCaster() {
  if (impl_ == nullptr) return;
  if (impl_->scene != nullptr) rtcReleaseScene(impl_->scene);
  if (impl_->device != nullptr) rtcReleaseDevice(impl_->device);
}

RayHit RayCaster::Cast(const CastRay& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayhit;
  rayhit.ray.org_x = static_cast<float>(ray.origin.x());
  rayhit.ray.org_y = static_cast<float>(ray.origin.y());
  rayhit.ray.org_z = static_cast<float>(ray.origin.z());
  rayhit.ray.dir_x = static_cast<float>(ray.direction.x());
  rayhit.ray.dir_y = static_cast<float>(ray.direction.y());
  rayhit.ray.dir_z = static_cast<float>(ray.direction.z());
  rayhit.ray.tnear = 0.0f;
  rayhit.ray.tfar = static_cast<float>(ray.max_range_m);
  rayhit.ray.time = 0.0f;
  // Debian's Embree is built with EMBREE_RAY_MASK: mask 0 hits nothing.
  rayhit.ray.mask = 0xFFFFFFFFu;
  rayhit.ray.id = 0;
  rayhit.ray.flags = 0;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rayhit);
  RayHit hit;
  if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.hit = true;
  hit.range_m = rayhit.ray.tfar;
  hit.triangle = rayhit.hit.primID;
  const Eigen::Vector3d& n = impl_->normals[hit.triangle];
  hit.normal = n.dot(ray.direction) > 0.0 ? Eigen::Vector3d(-n) : n;
  return hit;
}

void RayCaster::Cast(const std::vector<CastRay>& rays,
                     std::vector<RayHit>* hits) const {
  CHECK(hits != nullptr);
  hits->resize(rays.size());
  for (size_t k = 0; k < rays.size(); ++k) (*hits)[k] = Cast(rays[k]);
}

}  // namespace sim
}  // namespace mlndt
