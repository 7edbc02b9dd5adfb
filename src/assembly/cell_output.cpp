// Per-cell output of the bulk (Problem::cellFields): stresses and strains for fields.h5,
// evaluated through cell_stress.hpp from the same closures the assembly reads.
#include "poroseam/problem.hpp"

#include "cell_stress.hpp"

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
  out.fields.assign(3, CellField{});
  CellField &effective = out.fields[0], &total = out.fields[1], &strain = out.fields[2];
  effective.name = "effective_stress";
  total.name = "total_stress";
  strain.name = "strain";
  effective.units = total.units = "Pa";
  strain.units = "1";
  for (CellField *f : {&effective, &total, &strain}) {
    f->components = 9;
    f->values.reserve(9 * cells_.size());
  }
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(VecGetArrayRead(local, &ua));
  PetscCall(VecGetArrayRead(coords, &ca));
  std::vector<double> x, xc;
  for (size_t i = 0; i < cells_.size(); ++i) {
    const BulkCell &cell = cells_[i];
    const CellMaterial m = materialOf(*scene_, scene_->regions[cell.region], cell.size);
    const int n = closures_.closureSize(i), nc = closures_.coordinateSize(i);
    x.resize(n);
    xc.resize(nc);
    gatherClosure(ua, closures_.local(i), n, x.data());
    gatherClosure(ca, closures_.coordinates(i), nc, xc.data());
    const CellStressState s = cellStressAverage(
        elements_[cell.element], dim_, scene_->axisymmetric, m, scene_->hasPressure() && m.porous,
        xc.data(), x.data(),
        [&](int, const double *xq, const double eps[3][3], double stress[3][3]) {
          double s0[3][3];
          initialStress(xq, cell.region, s0);
          skeletonStress(m, eps, s0, stress);
        },
        [&](const double *xq) { return initialPressure(xq); });
    out.cells.push_back(cell.cell);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        effective.values.push_back(s.effective_stress[a][b]);
        total.values.push_back(s.total_stress[a][b]);
        strain.values.push_back(s.strain[a][b]);
      }
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  PetscCall(VecRestoreArrayRead(local, &ua));
  PetscFunctionReturn(0);
}

} // namespace poroseam
