#include "poroseam/probes.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace poroseam {

PetscErrorCode Probes::setup(DM dm, const Scene &scene)
{
  MPI_Comm comm;
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  dm_ = dm;
  dim_ = scene.dim;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  Vec coords;
  PetscSection csec;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  located_.assign(scene.probes.size(), Located());
  std::string error;
  for (size_t i = 0; i < scene.probes.size(); ++i) {
    Located &loc = located_[i];
    // On a region border, prefer a cell whose closure has pressure dofs (a porous cell):
    // the pressure there is the porous side's.
    PetscSection s;
    PetscCall(DMGetLocalSection(dm, &s));
    bool porous_found = false;
    for (PetscInt c = cStart; c < cEnd && !porous_found; ++c) {
      DMPolytopeType ct;
      PetscCall(DMPlexGetCellType(dm, c, &ct));
      if (DMPolytopeTypeGetDim(ct) != dim_ || isCohesive(ct)) continue;
      ReferenceElement e;
      PetscCall(ReferenceElement::create(ct, &e));
      PetscScalar *x = nullptr;
      PetscInt n = 0;
      PetscCall(DMPlexVecGetClosure(dm, csec, coords, c, &n, &x));
      double xi[3];
      const bool inside = locatePoint(e, x, scene.probes[i].x.data(), xi);
      PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, c, &n, &x));
      if (!inside) continue;
      PetscInt closure_dofs = 0, npts, *pts = nullptr;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &npts, &pts));
      for (PetscInt k = 0; k < npts; ++k) {
        PetscInt dof;
        PetscCall(PetscSectionGetDof(s, pts[2 * k], &dof));
        closure_dofs += dof;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &npts, &pts));
      const bool porous = closure_dofs == e.num_vertices * (dim_ + 1);
      if (loc.cell >= 0 && !porous) continue;
      loc.cell = c;
      loc.element = e;
      loc.phi.resize(e.num_vertices);
      e.evaluate(xi, loc.phi.data(), nullptr);
      porous_found = porous;
    }
    int mine = loc.cell >= 0 ? rank : size, owner = size;
    PetscCallMPI(MPI_Allreduce(&mine, &owner, 1, MPI_INT, MPI_MIN, comm));
    if (owner == size && error.empty()) {
      std::ostringstream msg;
      msg << "-probe_" << scene.probes[i].name << ": point (" << scene.probes[i].x[0] << ", "
          << scene.probes[i].x[1];
      if (dim_ == 3) msg << ", " << scene.probes[i].x[2];
      msg << ") is outside the mesh";
      error = msg.str();
    }
    if (owner != rank) loc.cell = -1;
  }
  PetscCall(checkOnAllRanks(comm, rank == 0 ? error : std::string()));
  PetscFunctionReturn(0);
}

PetscErrorCode Probes::evaluate(Vec local_solution, std::vector<double> &values) const
{
  PetscSection s;
  MPI_Comm comm;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm_, &comm));
  PetscCall(DMGetLocalSection(dm_, &s));
  const int per = valuesPerProbe();
  std::vector<double> mine(located_.size() * per, 0.0);
  std::vector<int> has_p(located_.size(), 0);
  for (size_t i = 0; i < located_.size(); ++i) {
    const Located &loc = located_[i];
    if (loc.cell < 0) continue;
    PetscScalar *x = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm_, s, local_solution, loc.cell, &n, &x));
    const int nv = loc.element.num_vertices, nu = nv * dim_;
    for (int a = 0; a < nv; ++a)
      for (int d = 0; d < dim_; ++d)
        mine[i * per + d] += loc.phi[a] * x[a * dim_ + d];
    if (n == nu + nv) {
      has_p[i] = 1;
      for (int a = 0; a < nv; ++a)
        mine[i * per + dim_] += loc.phi[a] * x[nu + a];
    }
    PetscCall(DMPlexVecRestoreClosure(dm_, s, local_solution, loc.cell, &n, &x));
  }
  values.assign(mine.size(), 0.0);
  std::vector<int> any_p(has_p.size(), 0);
  PetscCallMPI(
      MPI_Allreduce(mine.data(), values.data(), (int)mine.size(), MPI_DOUBLE, MPI_SUM, comm));
  PetscCallMPI(
      MPI_Allreduce(has_p.data(), any_p.data(), (int)has_p.size(), MPI_INT, MPI_MAX, comm));
  for (size_t i = 0; i < any_p.size(); ++i)
    if (!any_p[i]) values[i * per + dim_] = std::numeric_limits<double>::quiet_NaN();
  PetscFunctionReturn(0);
}

} // namespace poroseam
