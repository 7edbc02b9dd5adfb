// Bulk field output: HDF5 + XDMF time series that ParaView opens.
#pragma once

#include "poroseam/cell_fields.hpp"

#include <petscdm.h>
#include <string>
#include <vector>

namespace poroseam {

/// Writes vertex fields of the bulk mesh, one HDF5 file for the run plus an XDMF index that
/// ParaView reads as a time series. The solution DM's local section has the field
/// "displacement" (dim components on every vertex) and, when the scene has pressure, the
/// field "pressure" (1 component, only on vertices of porous regions). Vertices without
/// pressure (those of non-porous regions only) are written as NaN, which ParaView draws in its
/// NaN colour. Only bulk cells (not cohesive prisms) are written. Every dataset has a "units"
/// attribute.
class FieldWriter {
public:
  FieldWriter() = default;
  FieldWriter(const FieldWriter &) = delete;
  FieldWriter &operator=(const FieldWriter &) = delete;
  ~FieldWriter();

  /// Prepares `<dir>/<basename>.h5` and `<dir>/<basename>.xmf` for the solution DM. With
  /// `resume` (a restarted run), the files of the interrupted run are continued: their first
  /// resume->size() times are kept and later ones are overwritten by the next writes.
  PetscErrorCode open(DM solution_dm, const std::string &dir, const std::string &basename,
                      const std::vector<double> *resume = nullptr);
  /// The region index of every cell (constant: /cell_fields/region, the XDMF Cell attribute
  /// "region" of every time) and the regions' names (its HDF5 attribute "names", comma
  /// separated, in index order). Collective; call after open(), before the first write().
  PetscErrorCode writeRegions(const std::vector<PetscInt> &cells, const std::vector<int> &region,
                              const std::vector<std::string> &names);
  /// Names, units and shapes of the cell fields every write() will give (their values are
  /// ignored), so that the XDMF index of a restarted run lists the cell fields of the steps
  /// written before the restart even before its own first write.
  void declareCellFields(const CellFields &cells);
  /// Times written so far (for checkpoints).
  std::vector<double> times() const;
  /// Appends one time: displacement, pressure (if any), steady_pressure (the pressure of
  /// `local_initial`: the run passes the steady pore pressure, docs/outputs.md) and
  /// excess_pressure = pressure - steady_pressure. `local_solution` and `local_initial` are
  /// local vectors of solution_dm (with boundary values inserted); `local_initial` may be
  /// nullptr (then excess = pressure, steady = 0).
  /// `cells` (may be nullptr) adds per-cell quantities as /cell_fields/<name>/<step> and
  /// XDMF Cell attributes; every write of a run must give the same names.
  PetscErrorCode write(double time, Vec local_solution, Vec local_initial,
                       const CellFields *cells = nullptr);
  /// Finishes the XDMF index (also called by the destructor).
  PetscErrorCode close();

private:
  struct Impl;
  Impl *impl_ = nullptr;
};

} // namespace poroseam
