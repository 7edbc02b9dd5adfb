// Point probes: displacement and pressure interpolated at fixed points.
#pragma once

#include "poroseam/reference_element.hpp"
#include "poroseam/scene.hpp"
#include <petscdmplex.h>
#include <vector>

namespace poroseam {

class Probes {
public:
  /// Finds the cell of every probe (the lowest rank that holds one evaluates it). A probe
  /// outside the mesh is an input error naming the option.
  PetscErrorCode setup(DM dm, const Scene &scene);
  /// Values per probe: ux, uy[, uz], p (p is NaN where the cell has no pressure). Same on
  /// every rank.
  PetscErrorCode evaluate(Vec local_solution, std::vector<double> &values) const;
  int valuesPerProbe() const { return dim_ + 1; }

private:
  struct Located {
    PetscInt cell = -1; ///< on this rank, or -1 when another rank evaluates it
    ReferenceElement element;
    std::vector<double> phi;      ///< vertex basis at the probe (pressure)
    std::vector<double> node_phi; ///< node basis at the probe (displacement)
  };
  DM dm_ = nullptr;
  int dim_ = 0;
  std::vector<Located> located_;
};

} // namespace poroseam
