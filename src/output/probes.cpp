#include "poroseam/probes.hpp"

#include "poroseam/curved_nodes.hpp"
#include "poroseam/mesh_points.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
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
  PetscSection csec, s;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(DMGetLocalSection(dm, &s));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  const size_t np = scene.probes.size();
  located_.assign(np, Located());
  // One pass over the cells, testing every probe in each, instead of one pass per probe: the
  // coordinates of a cell are read once. A probe is done once it has a porous cell.
  std::vector<char> porous_found(np, 0);
  size_t open = np;
  // One reference element per cell type: building one (a PETSc reference cell DM) for every
  // cell scanned made this the bulk of the set-up on large meshes.
  std::map<DMPolytopeType, ReferenceElement> elements;
  // Curved cells (-mesh_geometry_order 2): located through their own (isoparametric) map.
  std::vector<double> places;
  Vec placed = nullptr;
  if (curvedNodes(dm)) {
    PetscCall(displacementNodePlaces(dm, places));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, (PetscInt)places.size(), places.data(),
                                    &placed));
  }
  std::vector<double> geometry;
  for (PetscInt c = cStart; c < cEnd && open > 0; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (DMPolytopeTypeGetDim(ct) != dim_ || isCohesive(ct)) continue;
    auto it = elements.find(ct);
    if (it == elements.end()) {
      ReferenceElement created;
      PetscCall(ReferenceElement::create(ct, &created, scene.displacement_order));
      it = elements.emplace(ct, created).first;
    }
    const ReferenceElement &e = it->second;
    PetscScalar *xv = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm, csec, coords, c, &n, &xv));
    const bool curved = placed != nullptr;
    if (curved) {
      PetscScalar *xp = nullptr;
      PetscInt npl = 0;
      PetscCall(DMPlexVecGetClosure(dm, s, placed, c, &npl, &xp));
      geometry.assign(xp, xp + e.num_nodes * dim_);
      PetscCall(DMPlexVecRestoreClosure(dm, s, placed, c, &npl, &xp));
    } else
      geometry.assign(xv, xv + n);
    const double *x = geometry.data();
    const int ng = curved ? e.num_nodes : e.num_vertices;
    // Bounding box of the vertices (curved: the nodes, padded by a tenth: a quadratic edge
    // may bulge past its nodes), padded: locatePoint accepts points up to its tolerance
    // (1e-8 in reference coordinates, i.e. a few 1e-8 of the cell's extent) outside the cell,
    // so a box padded by 1e-6 of the extent (plus round-off of the coordinates) never rejects
    // a cell it would accept, and the cheap box test spares the inverse map in all others.
    double lo[3], hi[3], pad = 0.0;
    for (int k = 0; k < dim_; ++k) {
      lo[k] = hi[k] = x[k];
      for (int a = 1; a < ng; ++a) {
        lo[k] = std::min(lo[k], (double)x[a * dim_ + k]);
        hi[k] = std::max(hi[k], (double)x[a * dim_ + k]);
      }
      pad = std::max(pad, (curved ? 0.1 : 1e-6) * (hi[k] - lo[k]) +
                              1e-12 * std::max(std::fabs(lo[k]), std::fabs(hi[k])));
    }
    for (size_t i = 0; i < np; ++i) {
      if (porous_found[i]) continue;
      const double *p = scene.probes[i].x.data();
      bool in_box = true;
      for (int k = 0; k < dim_ && in_box; ++k)
        in_box = p[k] >= lo[k] - pad && p[k] <= hi[k] + pad;
      if (!in_box) continue;
      double xi[3];
      if (!locatePoint(e, x, p, xi, curved)) continue;
      Located &loc = located_[i];
      // On a region border, prefer a cell whose closure has pressure dofs (a porous cell):
      // the pressure there is the porous side's.
      PetscInt closure_dofs = 0, npts, *pts = nullptr;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &npts, &pts));
      for (PetscInt k = 0; k < npts; ++k) {
        PetscInt dof;
        PetscCall(PetscSectionGetDof(s, pts[2 * k], &dof));
        closure_dofs += dof;
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &npts, &pts));
      const bool porous = closure_dofs == e.num_nodes * dim_ + e.num_vertices;
      if (loc.cell >= 0 && !porous) continue;
      loc.cell = c;
      loc.element = e;
      // The displacement from the node basis (order 2: the quadratic field itself), the
      // pressure from the vertex basis.
      loc.phi.resize(e.num_vertices);
      e.evaluate(xi, loc.phi.data(), nullptr);
      loc.node_phi.resize(e.num_nodes);
      e.evaluateNodes(xi, loc.node_phi.data(), nullptr);
      if (porous) porous_found[i] = 1, --open;
    }
    PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, c, &n, &xv));
  }
  PetscCall(VecDestroy(&placed));
  // The lowest rank that found a probe evaluates it.
  std::vector<int> mine(np), owner(np);
  for (size_t i = 0; i < np; ++i)
    mine[i] = located_[i].cell >= 0 ? rank : size;
  PetscCallMPI(MPI_Allreduce(mine.data(), owner.data(), (int)np, MPI_INT, MPI_MIN, comm));
  std::string error;
  for (size_t i = 0; i < np; ++i) {
    if (owner[i] == size && error.empty()) {
      std::ostringstream msg;
      msg << "-probe_" << scene.probes[i].name << ": point (" << scene.probes[i].x[0] << ", "
          << scene.probes[i].x[1];
      if (dim_ == 3) msg << ", " << scene.probes[i].x[2];
      msg << ") is outside the mesh";
      error = msg.str();
    }
    if (owner[i] != rank) located_[i].cell = -1;
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
    const int nv = loc.element.num_vertices, nn = loc.element.num_nodes, nu = nn * dim_;
    for (int a = 0; a < nn; ++a)
      for (int d = 0; d < dim_; ++d)
        mine[i * per + d] += loc.node_phi[a] * x[a * dim_ + d];
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
