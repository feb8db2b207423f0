// The tangent frame that turns a tangent-space normal (x = +u, y = +v, z = out; normal_map.h) into world
// space at a hit: N the geometric normal, T = dp/du made orthogonal to N (Gram-Schmidt) and normalised,
// B = N x T (equal to dp/dv normalised for the evaluator's shapes, whose parameterisations are orthogonal).
// Where dp/du vanishes (a sphere's poles) T = dp/dv x N instead. Surfaces are two-sided: seen from behind,
// N and B flip and T stays, so the frame remains right-handed and faces the viewer (the back sees the map
// mirrored along v).
#pragma once

#include "libbake/eval/shape_intersection.h"

namespace mbk {

struct SurfaceFrame {
  Vec3 T, B, N;
  Vec3 to_world(const Vec3& t) const { return t.x() * T + t.y() * B + t.z() * N; }
  Vec3 to_tangent(const Vec3& w) const { return Vec3(w.dot(T), w.dot(B), w.dot(N)); }  // the inverse (orthonormal)
};

SurfaceFrame surface_frame(const SurfaceHit& hit, const Vec3& to_viewer);

}  // namespace mbk
