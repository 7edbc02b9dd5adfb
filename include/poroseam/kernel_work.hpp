// Work arrays of the bulk cell kernel (src/assembly/cell_kernel.hpp), sized from the element
// (its number of displacement nodes) rather than for one element type, and kept across the
// cells of an assembly loop so that no cell allocates.
#pragma once

#include "poroseam/reference_element.hpp"

#include <vector>

namespace poroseam {

/// Work arrays of the cell kernel, sized from the element on first use and kept across the
/// cells of a loop (Problem::CellWork holds one).
struct CellKernelWork {
  struct Tensor {
    double v[3][3];
  };
  std::vector<Tensor> variation, stress_of; ///< per displacement dof
  std::vector<double> div, hoop;            ///< per displacement dof, per node
  PointGeometry point;
  void resize(int nodes, int dim)
  {
    const size_t nu = (size_t)nodes * dim;
    if (variation.size() < nu) variation.resize(nu), stress_of.resize(nu), div.resize(nu);
    if (hoop.size() < (size_t)nodes) hoop.resize(nodes);
  }
};

} // namespace poroseam
