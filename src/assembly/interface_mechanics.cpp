#include "poroseam/interface_mechanics.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/interfaces.hpp"

#include <cmath>
#include <map>

namespace poroseam {
namespace {

PetscErrorCode closureVertices(DM dm, PetscInt point, std::vector<PetscInt> &vertices)
{
  PetscInt vStart, vEnd, n, *pts = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetTransitiveClosure(dm, point, PETSC_TRUE, &n, &pts));
  vertices.clear();
  for (PetscInt i = 0; i < n; ++i)
    if (pts[2 * i] >= vStart && pts[2 * i] < vEnd) vertices.push_back(pts[2 * i]);
  PetscCall(DMPlexRestoreTransitiveClosure(dm, point, PETSC_TRUE, &n, &pts));
  PetscFunctionReturn(0);
}

PetscErrorCode vertexCoordinates(DM dm, PetscInt v, int dim, double x[3])
{
  Vec coords;
  PetscSection csec;
  const PetscScalar *a;
  PetscInt off;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(PetscSectionGetOffset(csec, v, &off));
  PetscCall(VecGetArrayRead(coords, &a));
  for (int d = 0; d < dim; ++d)
    x[d] = a[off + d];
  PetscCall(VecRestoreArrayRead(coords, &a));
  PetscFunctionReturn(0);
}

void normalise(double v[3])
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int d = 0; d < 3; ++d)
    v[d] /= n;
}

/// Traction on side 1 in global components, t = -p'_N e1 + tau_k e_(k+1), and its derivative
/// with respect to the global gap g = u2 - u1.
void globalTraction(const physics::ContactResponse &r, const double e[3][3], int dim, double t[3],
                    double T[3][3])
{
  const double local[3] = {-r.contact_pressure_effective, r.shear[0], r.shear[1]};
  for (int i = 0; i < dim; ++i) {
    t[i] = 0.0;
    for (int k = 0; k < dim; ++k)
      t[i] += local[k] * e[k][i];
  }
  // d t_local / d g_local: the first row is -d p'_N / d g.
  double D[3][3];
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      D[k][l] = (k == 0 ? -1.0 : 1.0) * r.tangent[k][l];
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) {
      double s = 0.0;
      for (int k = 0; k < dim; ++k)
        for (int l = 0; l < dim; ++l)
          s += e[k][i] * D[k][l] * e[l][j];
      T[i][j] = s;
    }
}

} // namespace

PetscErrorCode InterfaceMechanics::setup(DM dm, const Scene &scene, InitialStress initial_stress)
{
  PetscFunctionBeginUser;
  dm_ = dm;
  scene_ = &scene;
  dim_ = scene.dim;
  cells_.clear();
  initial_.clear();
  committed_.clear();
  if (scene.interfaces.empty()) PetscFunctionReturn(0);
  DMLabel iface, surface, side, normal;
  PetscCall(DMGetLabel(dm, kInterfaceLabel, &iface));
  PetscCall(DMGetLabel(dm, kInterfaceSurfaceLabel, &surface));
  PetscCall(DMGetLabel(dm, kInterfaceSideLabel, &side));
  PetscCall(DMGetLabel(dm, kInterfaceNormalLabel, &normal));
  std::map<std::pair<int, bool>, int> elementOf;
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    DMPolytopeType t;
    PetscCall(DMPlexGetCellType(dm, c, &t));
    if (!isCohesive(t)) continue;
    PetscInt vi, vs, vside, vn;
    PetscCall(DMLabelGetValue(iface, c, &vi));
    PetscCall(DMLabelGetValue(surface, c, &vs));
    PetscCall(DMLabelGetValue(side, c, &vside));
    PetscCall(DMLabelGetValue(normal, c, &vn));
    Cell cell;
    cell.cell = c;
    cell.iface = (int)vi - 1;
    cell.surface = (int)vs - 1;
    const Interface &in = scene.interfaces[cell.iface];
    const PetscInt *cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    const PetscInt face1 = cone[vside - 1], face2 = cone[2 - vside];
    DMPolytopeType ft;
    PetscCall(DMPlexGetCellType(dm, face1, &ft));
    const auto key = std::make_pair((int)ft, in.nodal_integration);
    if (!elementOf.count(key)) {
      ReferenceElement e;
      if (in.nodal_integration)
        PetscCall(ReferenceElement::createNodal(ft, &e));
      else
        PetscCall(ReferenceElement::create(ft, &e));
      elements_.push_back(e);
      elementOf[key] = (int)elements_.size() - 1;
    }
    cell.element = elementOf[key];
    const ReferenceElement &e = elements_[cell.element];

    // Closure slots of the side-1 face's vertices (in the face's own order, which the
    // reference element follows) and of their partners on side 2 (same coordinates).
    std::vector<PetscInt> all, v1, v2;
    PetscCall(closureVertices(dm, c, all));
    PetscCall(closureVertices(dm, face1, v1));
    PetscCall(closureVertices(dm, face2, v2));
    auto slotOf = [&](PetscInt v) {
      for (size_t k = 0; k < all.size(); ++k)
        if (all[k] == v) return (int)k;
      return -1;
    };
    std::vector<double> x1(v1.size() * dim_);
    for (size_t a = 0; a < v1.size(); ++a) {
      PetscCall(vertexCoordinates(dm, v1[a], dim_, &x1[a * dim_]));
      cell.side1_slot.push_back(slotOf(v1[a]));
      int partner = -1;
      double best = 1e300;
      for (size_t b = 0; b < v2.size(); ++b) {
        double y[3], d2 = 0.0;
        PetscCall(vertexCoordinates(dm, v2[b], dim_, y));
        for (int d = 0; d < dim_; ++d)
          d2 += (y[d] - x1[a * dim_ + d]) * (y[d] - x1[a * dim_ + d]);
        if (d2 < best) best = d2, partner = slotOf(v2[b]);
      }
      cell.side2_slot.push_back(partner);
    }
    // Local frame from cone[0]'s vertex order and the orientation found before distribution.
    {
      std::vector<PetscInt> v0;
      PetscCall(closureVertices(dm, cone[0], v0));
      std::vector<double> x0(v0.size() * dim_);
      for (size_t a = 0; a < v0.size(); ++a)
        PetscCall(vertexCoordinates(dm, v0[a], dim_, &x0[a * dim_]));
      double n[3];
      faceNormal(x0.data(), (int)v0.size(), dim_, n);
      const double sign = vn == 1 ? 1.0 : -1.0;
      for (int d = 0; d < 3; ++d)
        cell.frame[0][d] = sign * n[d];
      normalise(cell.frame[0]);
      double *e1 = cell.frame[0], *e2 = cell.frame[1], *e3 = cell.frame[2];
      if (dim_ == 2) {
        e2[0] = -e1[1], e2[1] = e1[0], e2[2] = 0.0;
        e3[0] = e3[1] = 0.0, e3[2] = 1.0;
      } else {
        double t[3] = {x0[3] - x0[0], x0[4] - x0[1], x0[5] - x0[2]};
        const double dot = t[0] * e1[0] + t[1] * e1[1] + t[2] * e1[2];
        for (int d = 0; d < 3; ++d)
          e2[d] = t[d] - dot * e1[d];
        normalise(e2);
        e3[0] = e1[1] * e2[2] - e1[2] * e2[1];
        e3[1] = e1[2] * e2[0] - e1[0] * e2[2];
        e3[2] = e1[0] * e2[1] - e1[1] * e2[0];
      }
    }
    // Initial state at each integration point, from the side-1 initial stress:
    // p'_N0 = -e1 . sigma'_0 e1, tau_0k = e_(k+1) . sigma'_0 e1 (capped by friction).
    cell.history = initial_.size();
    for (int q = 0; q < e.num_quadrature; ++q) {
      double x[3] = {0, 0, 0}, s0[3][3];
      for (int a = 0; a < e.num_vertices; ++a)
        for (int d = 0; d < dim_; ++d)
          x[d] += e.basis[q * e.num_vertices + a] * x1[a * dim_ + d];
      initial_stress(x, in.side1_tag, s0);
      double traction[3] = {0, 0, 0};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          traction[i] += s0[i][j] * cell.frame[0][j];
      physics::ContactInitial init;
      physics::ContactHistory history;
      double pn = 0.0;
      for (int i = 0; i < 3; ++i)
        pn -= cell.frame[0][i] * traction[i];
      init.contact_pressure_effective = std::max(pn, 0.0);
      double tau[2] = {0, 0}, norm = 0.0;
      for (int k = 0; k < dim_ - 1; ++k) {
        for (int i = 0; i < 3; ++i)
          tau[k] += cell.frame[k + 1][i] * traction[i];
        norm += tau[k] * tau[k];
      }
      norm = std::sqrt(norm);
      const double limit = in.friction * init.contact_pressure_effective;
      for (int k = 0; k < dim_ - 1; ++k)
        history.shear[k] = norm > limit ? tau[k] * limit / norm : tau[k];
      initial_.push_back(init);
      committed_.push_back(history);
    }
    cells_.push_back(cell);
  }
  PetscFunctionReturn(0);
}

template <class Kernel> PetscErrorCode InterfaceMechanics::loop(Vec local, Kernel &&kernel) const
{
  PetscSection s, csec;
  Vec coords;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  PetscCall(DMGetCoordinateSection(dm_, &csec));
  std::vector<double> x1;
  for (const Cell &cell : cells_) {
    const Interface &in = scene_->interfaces[cell.iface];
    const physics::ContactParameters params{in.normal_stiffness, in.tangential_stiffness,
                                            in.friction};
    const ReferenceElement &e = elements_[cell.element];
    PetscScalar *u = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm_, s, local, cell.cell, &n, &u));
    PetscScalar *xc = nullptr;
    PetscInt nc = 0;
    PetscCall(DMPlexVecGetClosure(dm_, csec, coords, cell.cell, &nc, &xc));
    x1.resize(e.num_vertices * dim_);
    for (int a = 0; a < e.num_vertices; ++a)
      for (int d = 0; d < dim_; ++d)
        x1[a * dim_ + d] = xc[cell.side1_slot[a] * dim_ + d];
    PetscCall(DMPlexVecRestoreClosure(dm_, csec, coords, cell.cell, &nc, &xc));
    for (int q = 0; q < e.num_quadrature; ++q) {
      const double *phi = &e.basis[q * e.num_vertices];
      InterfacePointState st;
      st.point = q;
      st.num_points = e.num_quadrature;
      st.face_vertices = e.num_vertices;
      st.face_coords = x1.data();
      st.weight = surfaceWeight(e, x1.data(), dim_, q);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          st.frame[i][j] = cell.frame[i][j];
      double g[3] = {0, 0, 0};
      for (int a = 0; a < e.num_vertices; ++a)
        for (int d = 0; d < dim_; ++d) {
          g[d] += phi[a] * (u[cell.side2_slot[a] * dim_ + d] - u[cell.side1_slot[a] * dim_ + d]);
          st.x[d] += phi[a] * x1[a * dim_ + d];
        }
      double local_gap[3] = {0, 0, 0};
      for (int k = 0; k < dim_; ++k)
        for (int d = 0; d < dim_; ++d)
          local_gap[k] += cell.frame[k][d] * g[d];
      st.gap_normal = local_gap[0];
      st.gap_tangential[0] = local_gap[1];
      st.gap_tangential[1] = local_gap[2];
      const size_t h = cell.history + q;
      st.response = physics::contactResponse(params, initial_[h], committed_[h], dim_ - 1,
                                             st.gap_normal, st.gap_tangential);
      st.opening = physics::mechanicalOpening(params, initial_[h], st.gap_normal);
      double T[3][3];
      globalTraction(st.response, cell.frame, dim_, st.traction, T);
      PetscCall(kernel(cell, q, phi, st, (int)n));
    }
    PetscCall(DMPlexVecRestoreClosure(dm_, s, local, cell.cell, &n, &u));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceMechanics::residual(Vec local, Vec f) const
{
  PetscSection s;
  std::vector<double> F;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm_, &s));
  const Cell *current = nullptr;
  auto flush = [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (current) PetscCall(DMPlexVecSetClosure(dm_, s, f, current->cell, F.data(), ADD_ALL_VALUES));
    PetscFunctionReturn(0);
  };
  PetscCall(loop(local,
                 [&](const Cell &cell, int q, const double *phi, const InterfacePointState &st,
                     int n) -> PetscErrorCode {
                   PetscFunctionBeginUser;
                   if (&cell != current) {
                     PetscCall(flush());
                     current = &cell;
                     F.assign(n, 0.0);
                   }
                   double t[3], T[3][3];
                   globalTraction(st.response, cell.frame, dim_, t, T);
                   // The interface pushes side 1 with t and side 2 with -t; residual = -(force on
                   // node).
                   for (size_t a = 0; a < cell.side1_slot.size(); ++a)
                     for (int d = 0; d < dim_; ++d) {
                       F[cell.side1_slot[a] * dim_ + d] -= st.weight * phi[a] * t[d];
                       F[cell.side2_slot[a] * dim_ + d] += st.weight * phi[a] * t[d];
                     }
                   PetscFunctionReturn(0);
                 }));
  PetscCall(flush());
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceMechanics::jacobian(Vec local, Mat J) const
{
  PetscSection s, gs;
  std::vector<double> K;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm_, &s));
  PetscCall(DMGetGlobalSection(dm_, &gs));
  const Cell *current = nullptr;
  int size = 0;
  auto flush = [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (current) PetscCall(DMPlexMatSetClosure(dm_, s, gs, J, current->cell, K.data(), ADD_VALUES));
    PetscFunctionReturn(0);
  };
  PetscCall(loop(local,
                 [&](const Cell &cell, int q, const double *phi, const InterfacePointState &st,
                     int n) -> PetscErrorCode {
                   PetscFunctionBeginUser;
                   if (&cell != current) {
                     PetscCall(flush());
                     current = &cell;
                     size = n;
                     K.assign((size_t)n * n, 0.0);
                   }
                   double t[3], T[3][3];
                   globalTraction(st.response, cell.frame, dim_, t, T);
                   // R_1a = -w phi_a t(g), R_2a = +w phi_a t(g), g = sum_b phi_b (u_2b - u_1b).
                   const int nf = (int)cell.side1_slot.size();
                   for (int a = 0; a < nf; ++a)
                     for (int b = 0; b < nf; ++b) {
                       const double w = st.weight * phi[a] * phi[b];
                       const int rows[2] = {cell.side1_slot[a], cell.side2_slot[a]};
                       const int cols[2] = {cell.side1_slot[b], cell.side2_slot[b]};
                       const double sr[2] = {-1.0, 1.0}, sc[2] = {-1.0, 1.0};
                       for (int r = 0; r < 2; ++r)
                         for (int c = 0; c < 2; ++c)
                           for (int i = 0; i < dim_; ++i)
                             for (int j = 0; j < dim_; ++j)
                               K[(size_t)(rows[r] * dim_ + i) * size + cols[c] * dim_ + j] +=
                                   sr[r] * sc[c] * w * T[i][j];
                     }
                   PetscFunctionReturn(0);
                 }));
  PetscCall(flush());
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceMechanics::commit(Vec local)
{
  std::vector<physics::ContactHistory> updated = committed_;
  PetscFunctionBeginUser;
  PetscCall(loop(local,
                 [&](const Cell &cell, int q, const double *, const InterfacePointState &st,
                     int) -> PetscErrorCode {
                   updated[cell.history + q] = st.response.updated;
                   return 0;
                 }));
  committed_.swap(updated);
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceMechanics::visit(
    Vec local, const std::function<void(int, int, PetscInt, const InterfacePointState &)> &f) const
{
  PetscFunctionBeginUser;
  PetscCall(loop(local,
                 [&](const Cell &cell, int, const double *, const InterfacePointState &st,
                     int) -> PetscErrorCode {
                   f(cell.iface, cell.surface, cell.cell, st);
                   return 0;
                 }));
  PetscFunctionReturn(0);
}

} // namespace poroseam
