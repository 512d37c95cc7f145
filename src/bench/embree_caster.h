// Embree 3 as the reference a user could pick instead of raycam's caster (benchmark only: raycam_embree is
// linked into raycam-cli for `bench speed`, never into raycam_core or the app).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "raycam/camera3d.h"
#include "raycam/colour_map.h"
#include "raycam/scene.h"

// Embree's handle types, declared as rtcore_device.h / rtcore_geometry.h do, so that including this header
// does not pull in Embree.
struct RTCDeviceTy;
struct RTCSceneTy;

namespace raycam::bench {

class EmbreeCaster {
 public:
  // One RTC_GEOMETRY_TYPE_SPHERE_POINT geometry (float x, y, z, r per sphere), committed here; an object's id
  // is its primitive id. Throws std::runtime_error with Embree's error text on failure.
  explicit EmbreeCaster(const Scene3D& scene);
  ~EmbreeCaster();
  EmbreeCaster(const EmbreeCaster&) = delete;
  EmbreeCaster& operator=(const EmbreeCaster&) = delete;

  double build_ms() const { return build_ms_; }  // wall time of rtcCommitScene (the BVH build)
  bool native_packet16() const;                  // RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED
  std::string isa_note() const;                  // e.g. "Embree 3.13.5, native packets: 4 8 16"

  // One primary ray per pixel of `camera`, exactly camera.primary_ray(row, column) rounded to float, into
  // `out` (image order, -1 and the background on a miss); `out` keeps its storage when the size is unchanged.
  // packet: 1 (rtcIntersect1 per ray) or 16 (rtcIntersect16 on 4×4 pixel blocks). threads ≥ 1: bands of 4
  // rows handed out through an atomic counter. Throws std::invalid_argument on another packet or threads < 1,
  // std::runtime_error if Embree reports an error.
  // ray_table (optional, rows × columns in image order): the rays made beforehand, so that only Embree's
  // traversal is timed (its best case; raycam's casters always make their own rays).
  void cast(const Camera3D& camera, int packet, int threads, ColourMap& out,
            const std::vector<Ray3D>* ray_table = nullptr) const;

 private:
  // Declared device first so that the scene, which references it, is released first.
  std::unique_ptr<RTCDeviceTy, void (*)(RTCDeviceTy*)> device_;
  std::unique_ptr<RTCSceneTy, void (*)(RTCSceneTy*)> scene_;
  std::vector<Rgb8> colours_;  // by sphere index, as the scene may not outlive the caster
  Rgb8 background_;
  double build_ms_ = 0.0;
};

}  // namespace raycam::bench
