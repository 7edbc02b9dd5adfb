// Interface output records (internal to src/output, for interface_writer.cpp): the state of
// every integration point and interface cell gathered from InterfaceAssembly::visit, the
// values written per point and per cell (cell values: point averages), and their units.
#pragma once

#include "poroseam/interface_assembly.hpp"

#include <string>
#include <vector>

namespace poroseam::interface_output {

struct PointRecord {
  PetscInt cell;
  int iface, surface, point, num_points;
  double x[3], weight, normal[3];
  double displacement_minus[3], displacement_plus[3];
  double gap_normal, opening, slip[2], slip_vector[3];
  double pressure, shear[2], shear_traction[3], traction[3];
  int state;
  // Hydraulics (0 without flow).
  double p3, aperture, aperture_rate, longitudinal_flux[3], transversal_flux1, transversal_flux2;
};

struct CellRecord {
  PetscInt cell;
  int iface, surface;
  int nodes;
  std::vector<double> coords;                                // nodes x dim
  std::vector<double> displacement_minus, displacement_plus; // nodes x 3
  size_t first, count;                                       // its points
};

// Quantities of one output location (a cell or a point).
struct Values {
  double gap_normal = 0, opening = 0, slip[2] = {0, 0}, slip_vector[3] = {0, 0, 0};
  double pressure = 0, shear[2] = {0, 0}, shear_traction[3] = {0, 0, 0}, traction[3] = {0, 0, 0};
  double mobilised = 0;
  int state = 0;
  double p3 = 0, aperture = 0, aperture_rate = 0, longitudinal_flux[3] = {0, 0, 0};
  double transversal_flux1 = 0, transversal_flux2 = 0;
  double displacement_minus[3] = {0, 0, 0}, displacement_plus[3] = {0, 0, 0}; // points only
};

/// |tau| / p'_N, 0 where p'_N = 0 (t tangential components).
double mobilised(double pressure, const double shear[2], int t);
/// The values written at an integration point.
Values pointValues(const PointRecord &p, int t);
/// The values written for a cell: averages over its points weighted by their area; state the
/// maximum, mobilised friction |mean tau| / mean p'_N.
Values cellValues(const CellRecord &c, const std::vector<PointRecord> &points, int t);
/// The "units" attribute of each dataset, by name. Areas and weights: m2 for a surface (3D,
/// and the rings of an axisymmetric model), m per metre out of plane in plane strain.
const char *unitsOf(const std::string &name, int dim, bool axisymmetric);
/// This rank's interface cells and integration points at the state `local` (in
/// InterfaceAssembly::visit order); checks the sequence visit hands out.
PetscErrorCode collect(const InterfaceAssembly &mech, int dim, Vec local,
                       const InterfaceRates &rates, std::vector<CellRecord> &cells,
                       std::vector<PointRecord> &points);

} // namespace poroseam::interface_output
