#pragma once
// Small fixed-size vector and tensor types used everywhere in Kessler.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cstdint>

namespace kessler {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Index = std::int64_t;  // global counts and offsets
using LocalIndex = std::int32_t;  // indices into one rank's arrays

inline Mat3 identity3() { return Mat3::Identity(); }

}  // namespace kessler
