#include "core/validation.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "raycam/limits.h"

namespace raycam::detail {

namespace {
[[noreturn]] void fail(const std::string& field, double value, const std::string& range) {
  std::ostringstream message;
  message << field << " = " << value << " is out of range: expected " << range;
  throw std::invalid_argument(message.str());
}
}  // namespace

bool is_coordinate(double value) { return std::isfinite(value) && std::abs(value) <= kMaxCoordinate; }

bool is_positive(double value) { return std::isfinite(value) && value > 0.0 && value <= kMaxCoordinate; }

void require_coordinate(double value, const std::string& field) {
  if (!is_coordinate(value)) fail(field, value, "a finite number in [-1e12, 1e12]");
}

void require_positive(double value, const std::string& field) {
  if (!is_positive(value)) fail(field, value, "a finite number in ]0, 1e12]");
}

void require_focal_distance(double value, const std::string& field) {
  if (!(value >= kMinFocalDistance && value <= kMaxFocalDistance))
    fail(field, value, "a number in [1e-9, 1e9]");
}

void require_angle(double value, const std::string& field) {
  if (!std::isfinite(value) || std::abs(value) > 1e6)
    fail(field, value, "a finite angle with |angle| <= 1e6 rad");
}

void require_res(double value, const std::string& field) {
  if (!(value > 0.0 && value <= 1.0)) fail(field, value, "a number in ]0, 1]");
}

void require_int_range(long long value, long long lo, long long hi, const std::string& field) {
  if (value < lo || value > hi) {
    std::ostringstream range;
    range << "an integer in [" << lo << ", " << hi << "]";
    fail(field, double(value), range.str());
  }
}

int useful_size(double res, int max_size, bool truncated) {
  const double n = truncated ? std::floor(res * max_size) : std::round(res * max_size);
  return int(std::clamp(n, 1.0, double(max_size)));
}

}  // namespace raycam::detail
