// Per-cell output quantities handed from the assembly (Problem::cellFields) to the field
// writer (FieldWriter::write): stresses, strains, and later the state of a plastic law.
#pragma once

#include <petscsystypes.h>
#include <string>
#include <vector>

namespace poroseam {

/// One per-cell quantity of one output time, for the cells of CellFields::cells.
struct CellField {
  std::string name;           ///< dataset and XDMF attribute name
  std::string units;          ///< its "units" attribute: "Pa", "1", ...
  int components = 1;         ///< 1 (XDMF Scalar) or 9 (Tensor, row-major 3 x 3)
  bool integer = false;       ///< written as integers (ids, states)
  std::vector<double> values; ///< `components` values per cell, cells in CellFields order
};

/// Per-cell quantities of one output time (Problem::cellFields), or the region of each cell;
/// and quantities recovered at the vertices (continuous stresses, stress_recovery.hpp).
struct CellFields {
  std::vector<PetscInt> cells; ///< local DMPlex cell points
  std::vector<CellField> fields;
  std::vector<PetscInt> vertices;       ///< local DMPlex vertex points (ghosts included)
  std::vector<CellField> vertex_fields; ///< `components` values per vertex of `vertices`
};

} // namespace poroseam
