// The skeleton (effective stress) law of a bulk region as the assembly sees it: a function of
// the strain at an integration point and the point's committed history that returns the
// stress, the consistent tangent, the yield state and the history to commit. The assembly
// calls it without knowing which law it is; skeleton_laws.cpp registers the laws of the
// materials. A law without history that is linear elastic is left empty: the cell kernel then
// takes its linear fast path with the region's moduli (cell_kernel.hpp), at no extra cost.
#pragma once

#include "poroseam/mohr_coulomb.hpp"
#include "poroseam/scene.hpp"

#include <functional>

namespace poroseam {

struct SkeletonLaw {
  /// sigma' (initial stress included), d sigma'/d eps, state and updated history at one point,
  /// from its initial effective stress, committed history and total strain (full 3x3).
  using Response = std::function<physics::SkeletonResponse(
      const double initial_stress[3][3], const physics::SkeletonHistory &committed,
      const double strain[3][3])>;
  Response response; ///< empty: linear elastic, the kernel uses the moduli alone
  /// The law keeps integration-point history (committed on accepted steps, checkpointed).
  bool hasHistory() const { return static_cast<bool>(response); }
};

/// The law of a region's skeleton (the registration: the one place that maps a material to
/// its law).
SkeletonLaw skeletonLawOf(const Region &r);

} // namespace poroseam
