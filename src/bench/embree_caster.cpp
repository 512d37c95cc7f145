#include "bench/embree_caster.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "raycam/parallel.h"

namespace raycam::bench {

namespace {
constexpr int kBandRows = 4;  // one 4×4 packet high, so packet 1 and 16 share the band split
constexpr float kInfinity = std::numeric_limits<float>::infinity();

const char* error_name(RTCError error) {
  switch (error) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}

// Embree 3 keeps error codes per thread and hands the text only to a callback, which collects it here.
void collect_error(void* text, RTCError, const char* message) {
  std::string& collected = *static_cast<std::string*>(text);
  if (collected.empty() && message) collected = message;
}

void throw_if_error(RTCDevice device, const char* step, const std::string& text) {
  const RTCError error = rtcGetDeviceError(device);
  if (error == RTC_ERROR_NONE) return;
  throw std::runtime_error(std::string("Embree: ") + step + ": " + (text.empty() ? error_name(error) : text));
}
}  // namespace

EmbreeCaster::EmbreeCaster(const Scene3D& scene)
    : device_(rtcNewDevice("threads=2"), &rtcReleaseDevice),
      scene_(nullptr, &rtcReleaseScene),
      background_(scene.background) {
  if (!device_)  // no device, no callback: the code is all there is
    throw std::runtime_error(std::string("Embree: rtcNewDevice: ") + error_name(rtcGetDeviceError(nullptr)));
  std::string error_text;
  rtcSetDeviceErrorFunction(device_.get(), &collect_error, &error_text);
  // error_text dies with this constructor, and cast() runs on threads that would race on it.
  struct Unhook {
    RTCDevice device;
    ~Unhook() { rtcSetDeviceErrorFunction(device, nullptr, nullptr); }
  } unhook{device_.get()};

  scene_.reset(rtcNewScene(device_.get()));
  throw_if_error(device_.get(), "rtcNewScene", error_text);
  // An empty scene gets no geometry: a zero-sized buffer is not worth Embree's corner cases.
  if (!scene.spheres.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* xyzr = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), scene.spheres.size()));
    if (xyzr) {
      for (const Sphere& sphere : scene.spheres) {
        *xyzr++ = float(sphere.centre.x);
        *xyzr++ = float(sphere.centre.y);
        *xyzr++ = float(sphere.centre.z);
        *xyzr++ = float(sphere.radius);
      }
      rtcCommitGeometry(geometry);
      rtcAttachGeometry(scene_.get(), geometry);  // the scene keeps its own reference
    }
    rtcReleaseGeometry(geometry);
    throw_if_error(device_.get(), "sphere geometry", error_text);
  }
  colours_.reserve(scene.spheres.size());
  for (const Sphere& sphere : scene.spheres) colours_.push_back(sphere.colour);

  const auto start = std::chrono::steady_clock::now();
  rtcCommitScene(scene_.get());
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  throw_if_error(device_.get(), "rtcCommitScene", error_text);
}

EmbreeCaster::~EmbreeCaster() = default;

bool EmbreeCaster::native_packet16() const {
  return rtcGetDeviceProperty(device_.get(), RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0;
}

std::string EmbreeCaster::isa_note() const {
  RTCDevice device = device_.get();
  std::string note = "Embree " +
                     std::to_string(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MAJOR)) + "." +
                     std::to_string(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MINOR)) + "." +
                     std::to_string(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_PATCH));
  std::string native;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) native += " 4";
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) native += " 8";
  if (native_packet16()) native += " 16";
  // A non-native packet size still works: Embree splits it into smaller packets or single rays.
  return note + ", native packets:" + (native.empty() ? std::string(" none") : native);
}

void EmbreeCaster::cast(const Camera3D& camera, int packet, int threads, ColourMap& out,
                        const std::vector<Ray3D>* ray_table) const {
  if (packet != 1 && packet != 16) throw std::invalid_argument("EmbreeCaster::cast: packet must be 1 or 16");
  if (threads < 1) throw std::invalid_argument("EmbreeCaster::cast: threads must be >= 1");
  const int rows = camera.rows(), columns = camera.columns();
  const std::size_t pixels = std::size_t(rows) * std::size_t(columns);
  out.resize(columns, rows);  // every pixel is written below, so no fill

  if (ray_table && ray_table->size() != pixels)
    throw std::invalid_argument("EmbreeCaster::cast: the ray table must hold one ray per pixel");
  auto ray_at = [&](int row, int column) {
    return ray_table ? (*ray_table)[std::size_t(row) * columns + std::size_t(column)] : camera.primary_ray(row, column);
  };
  auto store = [&](std::size_t index, unsigned geom_id, unsigned prim_id) {
    const bool hit = geom_id != RTC_INVALID_GEOMETRY_ID;
    out.ids[index] = hit ? int(prim_id) : -1;
    out.colours[index] = hit ? colours_[prim_id] : background_;
  };

  auto cast_single = [&](RTCIntersectContext& context, int row_begin, int row_end) {
    RTCRayHit rayhit;
    for (int row = row_begin; row < row_end; ++row)
      for (int column = 0; column < columns; ++column) {
        const Ray3D ray = ray_at(row, column);
        RTCRay& r = rayhit.ray;
        r.org_x = float(ray.origin.x);
        r.org_y = float(ray.origin.y);
        r.org_z = float(ray.origin.z);
        r.tnear = 0.0f;
        r.dir_x = float(ray.direction.x);
        r.dir_y = float(ray.direction.y);
        r.dir_z = float(ray.direction.z);
        r.time = 0.0f;
        r.tfar = kInfinity;
        r.mask = ~0u;
        r.id = 0u;
        r.flags = 0u;
        rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_.get(), &context, &rayhit);
        store(out.index(row, column), rayhit.hit.geomID, rayhit.hit.primID);
      }
  };

  auto cast_packets = [&](RTCIntersectContext& context, int row_begin, int row_end) {
    alignas(64) RTCRayHit16 rays;  // Embree requires 64-byte alignment for 16-wide packets
    alignas(64) int valid[16];
    for (int column_begin = 0; column_begin < columns; column_begin += 4) {
      for (int lane = 0; lane < 16; ++lane) {
        const int row = row_begin + lane / 4, column = column_begin + lane % 4;
        valid[lane] = row < row_end && column < columns ? -1 : 0;
        // Lanes past the image's edge repeat the edge pixel so that no lane holds garbage, then are masked.
        const Ray3D ray = ray_at(std::min(row, row_end - 1), std::min(column, columns - 1));
        RTCRay16& r = rays.ray;
        r.org_x[lane] = float(ray.origin.x);
        r.org_y[lane] = float(ray.origin.y);
        r.org_z[lane] = float(ray.origin.z);
        r.tnear[lane] = 0.0f;
        r.dir_x[lane] = float(ray.direction.x);
        r.dir_y[lane] = float(ray.direction.y);
        r.dir_z[lane] = float(ray.direction.z);
        r.time[lane] = 0.0f;
        r.tfar[lane] = kInfinity;
        r.mask[lane] = ~0u;
        r.id[lane] = 0u;
        r.flags[lane] = 0u;
        rays.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        rays.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
      }
      rtcIntersect16(valid, scene_.get(), &context, &rays);
      for (int lane = 0; lane < 16; ++lane)
        if (valid[lane])
          store(out.index(row_begin + lane / 4, column_begin + lane % 4), rays.hit.geomID[lane],
                rays.hit.primID[lane]);
    }
  };

  const int bands = (rows + kBandRows - 1) / kBandRows;
  std::atomic<int> error{RTC_ERROR_NONE};
  // The same persistent pool as raycam's casters (threads = 1 runs on the calling thread alone).
  raycam::detail::parallel_items(bands, threads, [&](int, int band) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // primary rays of neighbouring pixels: Embree's best case
    const int row_begin = band * kBandRows, row_end = std::min(rows, row_begin + kBandRows);
    if (packet == 1)
      cast_single(context, row_begin, row_end);
    else
      cast_packets(context, row_begin, row_end);
    // Error codes are per thread, so each band reads its own thread's.
    const RTCError own = rtcGetDeviceError(device_.get());
    if (own != RTC_ERROR_NONE) error.store(own);
  });
  if (error.load() != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: cast: ") + error_name(RTCError(error.load())));
}

}  // namespace raycam::bench
