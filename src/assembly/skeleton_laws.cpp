// Registration of the skeleton laws: which point law (physics/) a region's material uses.
// A new law is added here, in its own physics/ file and in its tests; the assembly does not
// change.
#include "poroseam/skeleton_law.hpp"

#include "poroseam/elastic.hpp"

#include <cmath>

namespace poroseam {

SkeletonLaw skeletonLawOf(const Region &r)
{
  SkeletonLaw law;
  switch (r.model) {
  case MaterialModel::elastic:
  case MaterialModel::biot:
    break; // linear elastic: the kernel's fast path
  case MaterialModel::mohr_coulomb: {
    physics::MohrCoulombParameters p;
    p.elastic = physics::lameFromYoung(r.young, r.poisson);
    p.cohesion = r.cohesion;
    p.friction_angle = r.friction_angle * M_PI / 180.0;
    p.dilation_angle = r.dilation_angle * M_PI / 180.0;
    p.tension_cutoff = r.tension_cutoff;
    law.response = [p](const double s0[3][3], const physics::SkeletonHistory &h,
                       const double eps[3][3]) {
      return physics::mohrCoulombResponse(p, s0, h, eps);
    };
    break;
  }
  }
  return law;
}

} // namespace poroseam
