// Per-cell output of the bulk (Problem::cellFields): stresses and strains for fields.h5,
// evaluated through cell_stress.hpp from the same closures the assembly reads. In a scene with
// skeleton laws that keep history (plasticity), also the plastic state: the law evaluated from
// the committed history at the state written (before it is committed, as the interfaces'
// outputs), its stress the effective stress written.
#include "poroseam/problem.hpp"

#include "cell_stress.hpp"

#include "poroseam/mesh_points.hpp"
#include "poroseam/stress_recovery.hpp"

#include <petscdmplex.h>

#include <algorithm>

namespace poroseam {

void Problem::cellRegions(std::vector<PetscInt> &cells, std::vector<int> &regions) const
{
  cells.clear();
  regions.clear();
  for (const BulkCell &c : cells_) {
    cells.push_back(c.cell);
    regions.push_back(c.region);
  }
}

PetscErrorCode Problem::cellFields(Vec local, CellFields &out) const
{
  Vec coords;
  const PetscScalar *ua, *ca;
  PetscFunctionBeginUser;
  out.cells.clear();
  const bool plastic = hasSkeletonHistory();
  out.fields.assign(plastic ? 5 : 3, CellField{});
  CellField &effective = out.fields[0], &total = out.fields[1], &strain = out.fields[2];
  if (plastic) {
    // Mean over the cell's integration points; the yield state 0 (elastic) when all are
    // elastic, else the largest physics::YieldState code (1 face, 2 edge, 3 apex, 4 tension).
    out.fields[3].name = "equivalent_plastic_strain";
    out.fields[3].units = "1";
    out.fields[4].name = "yield_state";
    out.fields[4].units = "1";
    out.fields[4].integer = true;
  }
  effective.name = "effective_stress";
  total.name = "total_stress";
  strain.name = "strain";
  effective.units = total.units = "Pa";
  strain.units = "1";
  for (CellField *f : {&effective, &total, &strain}) {
    f->components = 9;
    f->values.reserve(9 * cells_.size());
  }
  // Continuous effective and total stresses at the vertices (patch recovery from the
  // integration points): what a boundary's or a fault's stress is read from.
  PatchRecovery recovery(dim_, 18);
  PetscCall(recovery.reset(dm_));
  std::vector<PetscInt> cellVertices;
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &vStart, &vEnd));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(VecGetArrayRead(local, &ua));
  PetscCall(VecGetArrayRead(coords, &ca));
  std::vector<double> x, xc, xg;
  for (size_t i = 0; i < cells_.size(); ++i) {
    const BulkCell &cell = cells_[i];
    const CellMaterial m = materialOf(*scene_, scene_->regions[cell.region], cell.size);
    const int n = closures_.closureSize(i), nc = closures_.coordinateSize(i);
    x.resize(n);
    xc.resize(nc);
    gatherClosure(ua, closures_.local(i), n, x.data());
    gatherClosure(ca, closures_.coordinates(i), nc, xc.data());
    const bool curved = cellGeometry(i, ca, xg); // the points' places; xc: the vertices'
    double eqps = 0.0; // plastic state (cells whose law has history)
    int state = 0;
    PetscCall(closureVertices(dm_, cell.cell, cellVertices));
    const CellStressState s = cellStressAverage(
        elements_[cell.element], dim_, scene_->axisymmetric, m, scene_->hasPressure() && m.porous,
        xg.data(), x.data(),
        [&](int q, const double *xq, const double eps[3][3], double stress[3][3]) {
          double s0[3][3];
          initialStress(xq, cell.region, s0);
          if (cell.history == kNoHistory) {
            skeletonStress(m, eps, s0, stress);
            return;
          }
          const physics::SkeletonResponse r =
              laws_[cell.region].response(s0, skeleton_committed_[cell.history + q], eps);
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
              stress[a][b] = r.stress[a][b];
          eqps += r.updated.equivalent_plastic_strain / elements_[cell.element].num_quadrature;
          state = std::max(state, (int)r.state);
        },
        [&](const double *xq) { return initialPressure(xq); },
        [&](int, const double *xq, double, const double[3][3], const double effective_q[3][3],
            const double total_q[3][3]) {
          double values[18];
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
              values[3 * a + b] = effective_q[a][b];
              values[9 + 3 * a + b] = total_q[a][b];
            }
          // The vertices of the closure are the element's vertices, in its order.
          for (size_t k = 0; k < cellVertices.size(); ++k)
            recovery.add(cellVertices[k], &xc[k * dim_], xq, cell.size, values);
        },
        curved);
    out.cells.push_back(cell.cell);
    if (plastic) {
      out.fields[3].values.push_back(eqps);
      out.fields[4].values.push_back(state);
    }
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        effective.values.push_back(s.effective_stress[a][b]);
        total.values.push_back(s.total_stress[a][b]);
        strain.values.push_back(s.strain[a][b]);
      }
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscCall(VecRestoreArrayRead(local, &ua));

  std::vector<double> atVertices;
  PetscCall(recovery.finish(dm_, atVertices));
  out.vertices.clear();
  for (PetscInt v = vStart; v < vEnd; ++v)
    out.vertices.push_back(v);
  out.vertex_fields.assign(2, CellField{});
  out.vertex_fields[0].name = "recovered_effective_stress";
  out.vertex_fields[1].name = "recovered_total_stress";
  for (int f = 0; f < 2; ++f) {
    CellField &field = out.vertex_fields[f];
    field.units = "Pa";
    field.components = 9;
    field.values.resize(9 * out.vertices.size());
    for (size_t v = 0; v < out.vertices.size(); ++v)
      for (int c = 0; c < 9; ++c)
        field.values[9 * v + c] = atVertices[18 * v + 9 * f + c];
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
