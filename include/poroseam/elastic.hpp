// Linear elastic skeleton: pure point laws, no mesh. SI units throughout (Pa, m).
#pragma once

namespace poroseam::physics {

constexpr int kMaxDim = 3;

/// Lame constants of an isotropic linear elastic material.
struct ElasticModuli {
  double lambda = 0.0; ///< first Lame constant [Pa]
  double shear = 0.0;  ///< shear modulus G [Pa]

  /// Constrained (oedometric) modulus lambda + 2 G [Pa].
  double constrained() const { return lambda + 2.0 * shear; }
};

/// Lame constants from Young's modulus E [Pa] and Poisson's ratio nu.
ElasticModuli lameFromYoung(double young, double poisson);

/// Effective stress increment C : strain (tension positive), full 3x3 tensors.
/// In plane strain the out-of-plane strain components are zero but sigma_zz is not.
void elasticStress(const ElasticModuli &m, const double strain[3][3], double stress[3][3]);

/// Tangent C_ijkl = lambda d_ij d_kl + G (d_ik d_jl + d_il d_jk).
double elasticTangent(const ElasticModuli &m, int i, int j, int k, int l);

} // namespace poroseam::physics
