// Interface output records (see interface_records.hpp).
#include "interface_records.hpp"

#include <algorithm>
#include <cmath>

namespace poroseam::interface_output {

double mobilised(double pressure, const double shear[2], int t)
{
  double s = 0.0;
  for (int k = 0; k < t; ++k)
    s += shear[k] * shear[k];
  return pressure > 0.0 ? std::sqrt(s) / pressure : 0.0;
}

Values pointValues(const PointRecord &p, int t)
{
  Values v;
  v.gap_normal = p.gap_normal;
  v.opening = p.opening;
  v.pressure = p.pressure;
  for (int k = 0; k < 2; ++k)
    v.slip[k] = p.slip[k], v.shear[k] = p.shear[k];
  for (int d = 0; d < 3; ++d)
    v.slip_vector[d] = p.slip_vector[d], v.shear_traction[d] = p.shear_traction[d],
    v.traction[d] = p.traction[d];
  v.mobilised = mobilised(p.pressure, p.shear, t);
  v.state = p.state;
  v.p3 = p.p3;
  v.aperture = p.aperture;
  v.aperture_rate = p.aperture_rate;
  for (int d = 0; d < 3; ++d)
    v.longitudinal_flux[d] = p.longitudinal_flux[d];
  v.transversal_flux1 = p.transversal_flux1;
  v.transversal_flux2 = p.transversal_flux2;
  for (int d = 0; d < 3; ++d)
    v.displacement_minus[d] = p.displacement_minus[d],
    v.displacement_plus[d] = p.displacement_plus[d];
  return v;
}

Values cellValues(const CellRecord &c, const std::vector<PointRecord> &points, int t)
{
  Values v;
  double total = 0.0;
  for (size_t i = c.first; i < c.first + c.count; ++i)
    total += points[i].weight;
  const bool equal = !(total > 0.0); // degenerate face: plain mean
  for (size_t i = c.first; i < c.first + c.count; ++i) {
    const PointRecord &p = points[i];
    const double w = equal ? 1.0 / c.count : p.weight / total;
    v.gap_normal += w * p.gap_normal;
    v.opening += w * p.opening;
    v.pressure += w * p.pressure;
    for (int k = 0; k < 2; ++k)
      v.slip[k] += w * p.slip[k], v.shear[k] += w * p.shear[k];
    for (int d = 0; d < 3; ++d)
      v.slip_vector[d] += w * p.slip_vector[d], v.shear_traction[d] += w * p.shear_traction[d],
          v.traction[d] += w * p.traction[d];
    v.state = std::max(v.state, p.state);
    v.p3 += w * p.p3;
    v.aperture += w * p.aperture;
    v.aperture_rate += w * p.aperture_rate;
    for (int d = 0; d < 3; ++d)
      v.longitudinal_flux[d] += w * p.longitudinal_flux[d];
    v.transversal_flux1 += w * p.transversal_flux1;
    v.transversal_flux2 += w * p.transversal_flux2;
  }
  v.mobilised = mobilised(v.pressure, v.shear, t);
  return v;
}

const char *unitsOf(const std::string &name, int dim, bool axisymmetric)
{
  if (name == "area" || name == "weight") return dim == 3 || axisymmetric ? "m2" : "m";
  if (name == "geometry" || name == "gap_normal" || name == "opening" || name == "slip" ||
      name == "slip_vector" || name == "aperture" || name == "displacement_minus" ||
      name == "displacement_plus")
    return "m";
  if (name == "contact_pressure_effective" || name == "shear_stress" || name == "shear_traction" ||
      name == "traction" || name == "interface_pressure")
    return "Pa";
  if (name == "aperture_rate" || name == "transversal_flux1" || name == "transversal_flux2")
    return "m/s";
  if (name == "longitudinal_flux") return "m2/s";
  return "1"; // indices, ids, the normal, mobilised_friction, state
}

PetscErrorCode collect(const InterfaceAssembly &mech, int dim, Vec local,
                       const InterfaceRates &rates, std::vector<CellRecord> &cells,
                       std::vector<PointRecord> &points)
{
  const int d = dim, t = dim - 1;
  bool bad = false;

  PetscFunctionBeginUser;
  cells.clear();
  points.clear();
  PetscCall(mech.visit(
      local, rates, [&](int iface, int surface, PetscInt cell, const InterfacePointState &st) {
        if (cells.empty() || cells.back().cell != cell || st.point == 0) {
          CellRecord c;
          c.cell = cell;
          c.iface = iface;
          c.surface = surface;
          c.nodes = st.face_vertices;
          if (st.face_coords)
            c.coords.assign(st.face_coords, st.face_coords + st.face_vertices * d);
          c.displacement_minus.assign(3 * st.face_vertices, 0.0);
          c.displacement_plus.assign(3 * st.face_vertices, 0.0);
          if (st.face_displacement1 && st.face_displacement2)
            for (int a = 0; a < st.face_vertices; ++a)
              for (int i = 0; i < d; ++i) {
                c.displacement_minus[3 * a + i] = st.face_displacement1[a * d + i];
                c.displacement_plus[3 * a + i] = st.face_displacement2[a * d + i];
              }
          else
            bad = true;
          c.first = points.size();
          c.count = 0;
          if (st.point != 0 || !st.face_coords) bad = true;
          cells.push_back(std::move(c));
        }
        CellRecord &c = cells.back();
        ++c.count;
        PointRecord p;
        p.cell = cell;
        p.iface = iface;
        p.surface = surface;
        p.point = st.point;
        p.num_points = st.num_points;
        for (int i = 0; i < 3; ++i) {
          p.x[i] = i < d ? st.x[i] : 0.0;
          p.normal[i] = st.frame[0][i];
          p.traction[i] = st.traction[i];
          p.slip_vector[i] = 0.0;
          p.shear_traction[i] = 0.0;
        }
        p.weight = st.weight;
        // The displacements of both faces at the point, interpolated like the gap (the
        // displacement's node basis; linear faces: the barycentric weights of x among the
        // face's vertices).
        for (int i = 0; i < 3; ++i) {
          p.displacement_minus[i] = i < d ? st.displacement1[i] : 0.0;
          p.displacement_plus[i] = i < d ? st.displacement2[i] : 0.0;
        }
        p.gap_normal = st.gap_normal;
        p.opening = st.opening;
        p.pressure = st.response.contact_pressure_effective;
        for (int k = 0; k < 2; ++k) {
          p.slip[k] = k < t ? st.gap_tangential[k] : 0.0;
          p.shear[k] = k < t ? st.response.shear[k] : 0.0;
        }
        for (int k = 0; k < t; ++k)
          for (int i = 0; i < 3; ++i) {
            p.slip_vector[i] += p.slip[k] * st.frame[k + 1][i];
            p.shear_traction[i] += p.shear[k] * st.frame[k + 1][i];
          }
        p.state = static_cast<int>(st.response.state);
        const bool fl = st.flow;
        p.p3 = fl ? st.interface_pressure : 0.0;
        p.aperture = fl ? st.aperture : 0.0;
        p.aperture_rate = fl ? st.aperture_rate : 0.0;
        for (int i = 0; i < 3; ++i)
          p.longitudinal_flux[i] = fl && i < d ? st.longitudinal_flux[i] : 0.0;
        p.transversal_flux1 = fl ? st.transversal_flux1 : 0.0;
        p.transversal_flux2 = fl ? st.transversal_flux2 : 0.0;
        points.push_back(p);
      }));
  for (const CellRecord &c : cells)
    if (c.count != static_cast<size_t>(points[c.first].num_points) || c.nodes < 2 || c.nodes > 4)
      bad = true;
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "%s: unexpected integration point sequence from InterfaceAssembly::visit",
             "InterfaceWriter");
  PetscFunctionReturn(0);
}

} // namespace poroseam::interface_output
