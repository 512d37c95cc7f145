// Input checks shared by the core: each throws std::invalid_argument naming the field and the accepted range.
#pragma once

#include <string>

namespace raycam::detail {

// finite and within ±kMaxCoordinate
bool is_coordinate(double value);
void require_coordinate(double value, const std::string& field);
// finite, > 0 and ≤ kMaxCoordinate
bool is_positive(double value);
void require_positive(double value, const std::string& field);
// kMinFocalDistance ≤ value ≤ kMaxFocalDistance
void require_focal_distance(double value, const std::string& field);
// finite angle (radians), |value| ≤ 1e6 so that sin/cos keep meaning
void require_angle(double value, const std::string& field);
// 0 < res ≤ 1
void require_res(double value, const std::string& field);
// lo ≤ value ≤ hi
void require_int_range(long long value, long long lo, long long hi, const std::string& field);

// n = clamp(round(res·N), 1, N); with `truncated` (the classic mistake res_truncated) floor instead of round
int useful_size(double res, int max_size, bool truncated = false);

}  // namespace raycam::detail
