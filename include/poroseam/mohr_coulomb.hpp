// Skeleton laws of porous regions as pure point functions of the total small strain and the
// committed history: linear elastic, and Mohr-Coulomb perfect plasticity on effective stress
// (cohesion c, friction angle phi, dilation angle psi <= phi for non-associated flow, optional
// tension cut-off) with a return mapping in principal stresses and its consistent tangent.
// Tension positive (compression negative), as everywhere in poroseam. SI units (Pa, rad).
#pragma once

#include "poroseam/elastic.hpp"

#include <string>

namespace poroseam::physics {

/// Committed history of the skeleton at one integration point.
struct SkeletonHistory {
  double plastic_strain[3][3] = {};       ///< eps_p (symmetric, full 3x3; zz = hoop/out-of-plane)
  double equivalent_plastic_strain = 0.0; ///< accumulated sqrt(2/3 deps_p:deps_p) [-]
};

/// Which part of the yield surface the stress was returned to (an integer in fields.h5).
/// `tension`: any return that involves the tension cut-off (its plane, its edges with the
/// Mohr-Coulomb planes and its corner).
enum class YieldState { elastic = 0, face = 1, edge = 2, apex = 3, tension = 4 };

struct MohrCoulombParameters {
  ElasticModuli elastic;
  double cohesion = 0.0;        ///< c [Pa], >= 0
  double friction_angle = 0.0;  ///< phi [rad], 0 <= phi < pi/2 (phi = 0: Tresca)
  double dilation_angle = 0.0;  ///< psi [rad], 0 <= psi <= phi (non-associated if psi < phi)
  double tension_cutoff = -1.0; ///< sigma_t [Pa]: max principal effective stress; < 0: none
                                ///< (the apex c / tan(phi) limits tension); inert if >= apex
};

struct SkeletonResponse {
  double stress[3][3];        ///< effective stress sigma' (tension positive) [Pa]
  double tangent[3][3][3][3]; ///< consistent tangent d sigma' / d eps (minor symmetries)
  YieldState state;
  SkeletonHistory updated; ///< to commit if the step is accepted
};

/// Empty if the parameters are admissible, otherwise what is wrong with which value (the caller
/// prefixes the option or file it came from).
std::string mohrCoulombParameterError(const MohrCoulombParameters &p);

/// sigma' = initial_stress + C : (strain - eps_p), returned to the Mohr-Coulomb surface
/// (with tension cut-off) from the committed history. strain is the total small strain from the
/// reference state (full 3x3: plane strain has zero zz, axisymmetric has zz = u_r / r).
/// The parameters must pass mohrCoulombParameterError.
SkeletonResponse mohrCoulombResponse(const MohrCoulombParameters &p,
                                     const double initial_stress[3][3],
                                     const SkeletonHistory &committed, const double strain[3][3]);

/// The linear elastic skeleton in the same shape: sigma' = initial_stress + C : (strain - eps_p)
/// with the committed (normally zero) plastic strain, tangent C, state elastic, history unchanged.
SkeletonResponse elasticSkeletonResponse(const ElasticModuli &m, const double initial_stress[3][3],
                                         const SkeletonHistory &committed,
                                         const double strain[3][3]);

/// Eigenvalues of a symmetric 3x3 tensor in descending order and the orthonormal eigenvectors
/// as columns (vectors[i][a] = component i of eigenvector a); robust for repeated eigenvalues.
void symmetricEigen(const double a[3][3], double values[3], double vectors[3][3]);

} // namespace poroseam::physics
