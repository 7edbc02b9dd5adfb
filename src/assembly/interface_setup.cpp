// Setting up the interface integration points: geometry, local frames, initial contact
// stress and the closures of the cohesive cells (the loops over them are in
// interface_assembly.cpp).
#include "poroseam/interface_assembly.hpp"

#include "poroseam/closure_cache.hpp"
#include "poroseam/curved_nodes.hpp"
#include "poroseam/mesh_points.hpp"
#include "poroseam/collective_check.hpp"
#include "poroseam/interface_flow.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/mesh_points.hpp"

#include <cmath>
#include <map>

namespace poroseam {
namespace {

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

/// The points of `face`'s closure that carry displacement nodes (an entry in `offset`, the
/// displacement offsets of the cohesive cell's closure) and their positions (centroids of their
/// vertices): the face's vertices, and at order 2 its edges and a quadrilateral face itself.
PetscErrorCode nodePoints(DM dm, PetscInt face, const std::map<PetscInt, int> &offset, int dim,
                          std::vector<PetscInt> &points, std::vector<double> &centres)
{
  PetscInt n, *pts = nullptr;
  std::vector<PetscInt> vertices;
  PetscFunctionBeginUser;
  points.clear();
  centres.clear();
  PetscCall(DMPlexGetTransitiveClosure(dm, face, PETSC_TRUE, &n, &pts));
  for (PetscInt k = 0; k < n; ++k) {
    const PetscInt p = pts[2 * k];
    if (!offset.count(p)) continue;
    PetscCall(closureVertices(dm, p, vertices));
    double c[3] = {0, 0, 0}, x[3];
    for (PetscInt v : vertices) {
      PetscCall(vertexCoordinates(dm, v, dim, x));
      for (int d = 0; d < dim; ++d)
        c[d] += x[d] / (double)vertices.size();
    }
    points.push_back(p);
    centres.insert(centres.end(), c, c + dim);
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, face, PETSC_TRUE, &n, &pts));
  PetscFunctionReturn(0);
}

/// Index of the position in `centres` (dim each) nearest to x, -1 when there is none.
int nearest(const std::vector<double> &centres, int dim, const double x[3])
{
  int best = -1;
  double dmin = 1e300;
  for (int k = 0; k < (int)centres.size() / dim; ++k) {
    double d2 = 0.0;
    for (int d = 0; d < dim; ++d)
      d2 += std::pow(centres[k * dim + d] - x[d], 2);
    if (d2 < dmin) dmin = d2, best = k;
  }
  return best;
}

void normalise(double v[3])
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int d = 0; d < 3; ++d)
    v[d] /= n;
}

} // namespace

PetscErrorCode InterfaceAssembly::setup(DM dm, const Scene &scene, InitialStress initial_stress,
                                        InitialPressure initial_pressure)
{
  PetscFunctionBeginUser;
  dm_ = dm;
  scene_ = &scene;
  initial_pressure_ = std::move(initial_pressure);
  initial_stress_ = std::move(initial_stress);
  dim_ = scene.dim;
  cells_.clear();
  initial_.clear();
  committed_.clear();
  closures_ = ClosureCache();
  if (scene.interfaces.empty()) PetscFunctionReturn(0);
  DMLabel iface, surface, side, normal;
  PetscCall(DMGetLabel(dm, kInterfaceLabel, &iface));
  PetscCall(DMGetLabel(dm, kInterfaceSurfaceLabel, &surface));
  PetscCall(DMGetLabel(dm, kInterfaceSideLabel, &side));
  PetscCall(DMGetLabel(dm, kInterfaceNormalLabel, &normal));
  std::map<std::pair<int, bool>, int> elementOf;
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  std::string error;
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
    const int order = scene.displacement_order;
    if (order > 1 && in.nodal_integration && ft == DM_POLYTOPE_TRIANGLE && error.empty())
      error = "-interface_" + in.name + "_integration nodal: at -displacement_order 2 the " +
              "nodal rule of a triangular face (6 nodes of P2) gives its vertices zero weight, " +
              "leaving them without a contact spring; use gauss (6 points) on triangular faces";
    if (!error.empty()) continue;
    const auto key = std::make_pair((int)ft, in.nodal_integration);
    if (!elementOf.count(key)) {
      ReferenceElement e;
      if (in.nodal_integration)
        PetscCall(ReferenceElement::createNodal(ft, &e, order));
      else
        PetscCall(ReferenceElement::create(ft, &e, order));
      elements_.push_back(e);
      elementOf[key] = (int)elements_.size() - 1;
    }
    cell.element = elementOf[key];
    const auto gkey = std::make_pair((int)ft, false);
    if (!elementOf.count(gkey)) {
      ReferenceElement g;
      PetscCall(ReferenceElement::create(ft, &g, order));
      elements_.push_back(g);
      elementOf[gkey] = (int)elements_.size() - 1;
    }
    cell.gauss_element = elementOf[gkey];
    const ReferenceElement &e = elements_[cell.element];

    // Closure offsets. PETSc orders a closure field by field, point by point: all
    // displacements, then pressures, then interface pressures (lateral edges). The coordinate
    // closure lists the same points (vertices only carry coordinates).
    PetscSection sec, csec;
    PetscCall(DMGetLocalSection(dm, &sec));
    PetscCall(DMGetCoordinateSection(dm, &csec));
    PetscInt numFields;
    PetscCall(PetscSectionGetNumFields(sec, &numFields));
    std::map<PetscInt, int> offset[3], coordinateOffset;
    std::vector<PetscInt> lateral;
    {
      PetscInt n, *pts = nullptr;
      PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
      int running = 0, xrunning = 0;
      for (PetscInt f = 0; f < numFields; ++f)
        for (PetscInt k = 0; k < n; ++k) {
          PetscInt dof;
          PetscCall(PetscSectionGetFieldDof(sec, pts[2 * k], f, &dof));
          if (dof) offset[f][pts[2 * k]] = running;
          running += (int)dof;
        }
      PetscInt xStart, xEnd; // the coordinate section's chart holds the vertices only
      PetscCall(PetscSectionGetChart(csec, &xStart, &xEnd));
      for (PetscInt k = 0; k < n; ++k) {
        PetscInt dof = 0;
        if (pts[2 * k] >= xStart && pts[2 * k] < xEnd)
          PetscCall(PetscSectionGetDof(csec, pts[2 * k], &dof));
        if (dof) coordinateOffset[pts[2 * k]] = xrunning;
        xrunning += (int)dof;
        DMPolytopeType pt;
        PetscCall(DMPlexGetCellType(dm, pts[2 * k], &pt));
        if (pt == DM_POLYTOPE_POINT_PRISM_TENSOR) lateral.push_back(pts[2 * k]);
      }
      PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &pts));
    }
    auto offsetOf = [&](int field, PetscInt point) {
      if (field >= numFields) return -1;
      const auto it = offset[field].find(point);
      return it == offset[field].end() ? -1 : it->second;
    };
    // Side-1 face vertices in the face's own order (the reference element follows it), their
    // partners on side 2 (same coordinates) and the lateral edge joining each pair.
    std::vector<PetscInt> v1, v2;
    PetscCall(closureVertices(dm, face1, v1));
    PetscCall(closureVertices(dm, face2, v2));
    std::vector<double> x1(v1.size() * dim_);
    cell.flow = in.flow;
    const int side1_region = scene.regionIndexOfTag(in.side1_tag);
    cell.gap_water = !in.flow && scene.drained && side1_region >= 0 &&
                     scene.regions[side1_region].porous() && scene.gravity > 0.0;
    cell.porous1 = cell.porous2 = true;
    for (size_t a = 0; a < v1.size(); ++a) {
      PetscCall(vertexCoordinates(dm, v1[a], dim_, &x1[a * dim_]));
      PetscInt partner = -1;
      double best = 1e300;
      for (size_t b = 0; b < v2.size(); ++b) {
        double y[3], d2 = 0.0;
        PetscCall(vertexCoordinates(dm, v2[b], dim_, y));
        for (int d = 0; d < dim_; ++d)
          d2 += (y[d] - x1[a * dim_ + d]) * (y[d] - x1[a * dim_ + d]);
        if (d2 < best) best = d2, partner = v2[b];
      }
      cell.x1.push_back(coordinateOffset.count(v1[a]) ? coordinateOffset[v1[a]] : -1);
      cell.p1.push_back(offsetOf(1, v1[a]));
      cell.p2.push_back(offsetOf(1, partner));
      cell.porous1 = cell.porous1 && cell.p1.back() >= 0;
      cell.porous2 = cell.porous2 && cell.p2.back() >= 0;
      int p3 = -1;
      for (PetscInt edge : lateral) {
        const PetscInt *econe;
        PetscCall(DMPlexGetCone(dm, edge, &econe));
        if (econe[0] == v1[a] || econe[1] == v1[a]) p3 = offsetOf(2, edge);
      }
      cell.p3.push_back(p3);
      cell.flow = cell.flow && p3 >= 0;
    }
    // Displacement nodes of the face element (its node basis, closure order of the reference
    // face), each matched by position to the point of each face that carries it: at order 1
    // the vertices, at order 2 also the edges (midpoints) and a quadrilateral face (centre).
    // The node's position is the vertex map at its reference coordinates; a point's is the
    // centroid of its vertices (straight-sided faces).
    {
      std::vector<PetscInt> pts1, pts2;
      std::vector<double> c1, c2;
      PetscCall(nodePoints(dm, face1, offset[0], dim_, pts1, c1));
      PetscCall(nodePoints(dm, face2, offset[0], dim_, pts2, c2));
      std::vector<double> phi(e.num_vertices);
      double size2 = 0.0;
      for (size_t a = 1; a < v1.size(); ++a)
        for (int d = 0; d < dim_; ++d)
          size2 += std::pow(x1[a * dim_ + d] - x1[d], 2);
      for (int a = 0; a < e.num_nodes; ++a) {
        e.evaluate(&e.node_coords[a * e.dim], phi.data(), nullptr);
        double X[3] = {0, 0, 0};
        for (int b = 0; b < e.num_vertices; ++b)
          for (int d = 0; d < dim_; ++d)
            X[d] += phi[b] * x1[b * dim_ + d];
        const int k1 = nearest(c1, dim_, X), k2 = nearest(c2, dim_, X);
        double d1 = 0.0, d2 = 0.0;
        for (int d = 0; d < dim_ && k1 >= 0 && k2 >= 0; ++d) {
          d1 += std::pow(c1[k1 * dim_ + d] - X[d], 2);
          d2 += std::pow(c2[k2 * dim_ + d] - X[d], 2);
        }
        PetscCheck(k1 >= 0 && k2 >= 0 && d1 <= 1e-16 * size2 && d2 <= 1e-16 * size2,
                   PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "cohesive cell %" PetscInt_FMT ": no displacement node of its faces at node %d "
                   "of the face element",
                   c, a);
        cell.u1.push_back(offset[0].at(pts1[k1]));
        cell.u2.push_back(offset[0].at(pts2[k2]));
      }
      // The vertices among the nodes (output reports the faces' vertex displacements).
      for (int b = 0; b < e.num_vertices; ++b) {
        int found = -1;
        for (int a = 0; a < e.num_nodes; ++a) {
          double dist = 0.0;
          for (int d = 0; d < e.dim; ++d)
            dist += std::fabs(e.node_coords[a * e.dim + d] - e.vertex_coords[b * e.dim + d]);
          if (dist < 1e-12) found = a;
        }
        PetscCheck(found >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "a face vertex is not a node");
        cell.vertex_node.push_back(found);
      }
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
    // Initial state at each integration point, from the side-1 initial total stress
    // sigma_0 = sigma'_0 - alpha p_0 I: the faces carry sigma_0 e1 = -(p'_N0 + p_gap) e1 + tau_0,
    // p_gap the water pressure in the gap (p3 with flow, the pore pressure of a drained scene's
    // gap water, none otherwise), so p'_N0 = -e1 . sigma_0 e1 - p_gap and
    // tau_0k = e_(k+1) . sigma_0 e1 (capped by friction): in equilibrium for any alpha.
    cell.history = initial_.size();
    for (int q = 0; q < e.num_quadrature; ++q) {
      double x[3] = {0, 0, 0};
      for (int a = 0; a < e.num_vertices; ++a)
        for (int d = 0; d < dim_; ++d)
          x[d] += e.basis[q * e.num_vertices + a] * x1[a * dim_ + d];
      initialContact(in, x, cell.frame, scene.geostatic && (cell.flow || cell.gap_water),
                     initial_.size());
    }
    cells_.push_back(cell);
  }
  PetscCall(checkOnAllRanks(PetscObjectComm((PetscObject)dm), error));
  std::vector<PetscInt> points;
  for (const Cell &cell : cells_)
    points.push_back(cell.cell);
  PetscCall(closures_.setup(dm, points));
  places_.clear();
  point_frames_.clear();
  // The ring weights (2 pi r, interface_assembly.cpp) take r from the straight face; curved
  // faces in axisymmetry would need r from the curved map as well: not verified, so refused.
  // (An axisymmetric section's boundaries are the caisson's straight lines: nothing is lost.)
  PetscCheck(!(curvedNodes(dm) && scene.axisymmetric && !scene.interfaces.empty()),
             PetscObjectComm((PetscObject)dm), PETSC_ERR_USER_INPUT,
             "-mesh_geometry_order 2 with -axisymmetric and -interfaces: curved interface faces "
             "are not available in axisymmetry; use -mesh_geometry_order 1 (straight-sided "
             "cells)");
  if (curvedNodes(dm)) PetscCall(setupCurved(dm));
  PetscFunctionReturn(0);
}

void InterfaceAssembly::initialContact(const Interface &in, const double x[3],
                                       const double frame[3][3], bool pore_water, size_t h)
{
  // Initial state at an integration point, from the side-1 initial total stress
  // sigma_0 = sigma'_0 - alpha p_0 I: the faces carry sigma_0 e1 = -(p'_N0 + p_gap) e1 + tau_0,
  // p_gap the water pressure in the gap (p3 with flow, the pore pressure of a drained scene's
  // gap water, none otherwise), so p'_N0 = -e1 . sigma_0 e1 - p_gap and
  // tau_0k = e_(k+1) . sigma_0 e1 (capped by friction): in equilibrium for any alpha.
  double s0[3][3];
  initial_stress_(x, in.side1_tag, s0);
  double traction[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      traction[i] += s0[i][j] * frame[0][j];
  physics::ContactInitial init;
  physics::ContactHistory history;
  double pn = 0.0;
  for (int i = 0; i < 3; ++i)
    pn -= frame[0][i] * traction[i];
  if (pore_water) pn -= initial_pressure_(x);
  init.contact_pressure_effective = std::max(pn, 0.0);
  double tau[2] = {0, 0}, norm = 0.0;
  for (int k = 0; k < dim_ - 1; ++k) {
    for (int i = 0; i < 3; ++i)
      tau[k] += frame[k + 1][i] * traction[i];
    norm += tau[k] * tau[k];
  }
  norm = std::sqrt(norm);
  const double limit = in.friction * init.contact_pressure_effective;
  for (int k = 0; k < dim_ - 1; ++k)
    history.shear[k] = norm > limit ? tau[k] * limit / norm : tau[k];
  if (h < initial_.size()) {
    initial_[h] = init;
    committed_[h] = history;
  } else {
    initial_.push_back(init);
    committed_.push_back(history);
  }
}

PetscErrorCode InterfaceAssembly::setupCurved(DM dm)
{
  // Curved faces: the side-1 face's node places (the geometry of the isoparametric face), and
  // at each integration point the curved face's normal with the cell's first tangent turned
  // onto it (the frame moves smoothly over the face); the initial state again in that frame.
  std::vector<double> places;
  PetscFunctionBeginUser;
  PetscCall(displacementNodePlaces(dm, places));
  size_t stride = 0;
  for (const Cell &cell : cells_)
    stride = std::max(stride, cell.u1.size() * (size_t)dim_);
  places_stride_ = stride;
  places_.assign(cells_.size() * stride, 0.0);
  point_frames_.assign(initial_.size() * 9, 0.0);
  for (size_t i = 0; i < cells_.size(); ++i) {
    const Cell &cell = cells_[i];
    const ReferenceElement &e = elements_[cell.element];
    const Interface &in = scene_->interfaces[cell.iface];
    const PetscInt *local = closures_.local(i);
    double *xg = &places_[i * stride];
    for (size_t a = 0; a < cell.u1.size(); ++a)
      for (int d = 0; d < dim_; ++d)
        xg[a * dim_ + d] = places[local[cell.u1[a] + d]];
    for (int q = 0; q < e.num_quadrature; ++q) {
      const size_t h = cell.history + q;
      double(*frame)[3] = reinterpret_cast<double(*)[3]>(&point_frames_[h * 9]);
      surfaceNormal(e, xg, dim_, q, true, cell.frame[0], frame[0]);
      double *e1 = frame[0], *e2 = frame[1], *e3 = frame[2];
      const double dot = cell.frame[1][0] * e1[0] + cell.frame[1][1] * e1[1] + cell.frame[1][2] * e1[2];
      double length = 0.0;
      for (int d = 0; d < 3; ++d) {
        e2[d] = cell.frame[1][d] - dot * e1[d];
        length += e2[d] * e2[d];
      }
      for (int d = 0; d < 3; ++d)
        e2[d] /= std::sqrt(length);
      e3[0] = e1[1] * e2[2] - e1[2] * e2[1];
      e3[1] = e1[2] * e2[0] - e1[0] * e2[2];
      e3[2] = e1[0] * e2[1] - e1[1] * e2[0];
      if (dim_ == 2) e3[0] = e3[1] = 0.0, e3[2] = 1.0;
      double x[3] = {0, 0, 0};
      for (int a = 0; a < e.num_nodes; ++a)
        for (int d = 0; d < dim_; ++d)
          x[d] += e.node_basis[q * e.num_nodes + a] * xg[a * dim_ + d];
      initialContact(in, x, frame, scene_->geostatic && (cell.flow || cell.gap_water), h);
    }
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
