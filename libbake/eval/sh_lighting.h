// Distant lighting as spherical harmonics of order 2 (9 coefficients per RGB channel), the way a shader
// receives an environment: Ramamoorthi & Hanrahan, "An Efficient Representation for Irradiance
// Environment Maps", SIGGRAPH 2001. (project_lat_long also projects to any order, for the histogram effect.)
//
// Basis: libbake/core/sh_basis.h (real, orthonormal, no Condon-Shortley phase, k = l (l + 1) + m), evaluated
// on world directions (x, y, z):
//   Y00 = 1/(2 sqrt(pi))
//   Y1-1 = c1 y,  Y10 = c1 z,  Y11 = c1 x                          c1 = sqrt(3 / (4 pi))
//   Y2-2 = c2 xy, Y2-1 = c2 yz, Y20 = c3 (3 z^2 - 1), Y21 = c2 xz,  c2 = sqrt(15 / (4 pi)), c3 = sqrt(5 / (16 pi))
//   Y22 = c4 (x^2 - y^2)                                            c4 = sqrt(15 / (16 pi))
//
// Lat-long maps: texel (i, row) of a W x H map is the direction at phi = 2 pi (i + 1/2) / W,
// theta = pi (row + 1/2) / H, d = (sin(theta) cos(phi), cos(theta), sin(theta) sin(phi)): row 0 is the
// zenith (+Y), the centre column faces -X, and seen from inside the map is not mirrored. Projection sums
// L(d) Y(d) dOmega over texels in double, with each texel's exact solid angle
// dOmega = (2 pi / W)(cos(theta_top) - cos(theta_bottom)) (so a constant map projects exactly).
//
// Diffuse: irradiance E(n) = sum_l A_l sum_m L_lm Y_lm(n) with the exact cosine-lobe convolution
// A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4 [Ramamoorthi01, Eq. 8]; radiance leaving = albedo / pi * E.
//
// Specular (an approximation, used identically by the baseline, the effects and the reference):
// the microfacet lobe is replaced by a von Mises-Fisher lobe around the mirror direction r = 2 (n.v) n - v
// with kappa = 1 / (2 alpha^2): a slope spread of variance alpha^2 / 2 per axis is a normal spread of
// kappa_n = 2 / alpha^2, and reflection doubles angles (kappa_r = kappa_n / 4). Its convolution with the
// SH radiance is exact per band (Funk-Hecke): Lambda_l = I_{l+1/2}(kappa) / I_{1/2}(kappa), i.e.
// Lambda_0 = 1, Lambda_1 = coth(kappa) - 1/kappa, Lambda_2 = 1 - 3 Lambda_1 / kappa. The specular
// radiance is F_Schlick(F0, n.v) * sum_l Lambda_l sum_m L_lm Y_lm(r): masking-shadowing and the lobe's
// stretching at grazing angles are ignored. Order-2 reconstructions can dip below zero near sharp
// lights; radiance and irradiance are clamped at 0 per channel.
#pragma once

#include <array>
#include <vector>

#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk {

inline constexpr int kShCount = 9;
using ShBasis = std::array<double, kShCount>;
using ShCoefficients = std::array<Vec3, kShCount>;  // RGB per basis function

ShBasis sh_basis(const Vec3& unit_direction);
Vec3 lat_long_direction(double phi, double theta);
// Its inverse: (phi in [0, 2 pi), theta in [0, pi]) of a unit direction.
Vec2 lat_long_angles(const Vec3& unit_direction);
// Projects a lat-long radiance map (1 channel = grey, else the first three are RGB).
ShCoefficients project_lat_long(const Image& map);
// The same to any order L (0..kMaxShOrder of libbake/core/sh_basis.h): (L + 1)^2 RGB coefficients, k = l (l + 1) + m.
// Above order 2 each texel is sampled n x n times (n = ceil(4 L / H), at most 16) so that the projection is that of
// the piecewise-constant map rather than an aliased one.
std::vector<Vec3> project_lat_long(const Image& map, int order);
// Coefficients of a constant radiance from every direction.
ShCoefficients constant_radiance_sh(const Vec3& radiance);

Vec3 sh_radiance(const ShCoefficients& sh, const Vec3& unit_direction);
Vec3 sh_irradiance(const ShCoefficients& sh, const Vec3& unit_normal);
// The vMF band factors Lambda_0..2 for concentration kappa > 0.
std::array<double, 3> vmf_band_factors(double kappa);
double specular_lobe_kappa(double alpha);
// sum_l Lambda_l(kappa) sum_m L_lm Y_lm(r), clamped at 0.
Vec3 sh_lobe_radiance(const ShCoefficients& sh, const Vec3& unit_direction, double kappa);

}  // namespace mbk
