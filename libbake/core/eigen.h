// Eigen aliases used across libbake. Vectors are double unless a name says otherwise: numerical code
// computes in double and stores float.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mbk {
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec3f = Eigen::Vector3f;
using Mat2 = Eigen::Matrix2d;
}  // namespace mbk
