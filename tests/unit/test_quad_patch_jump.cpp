// Interface patch test at the solver level (issue 25, item 6): a block on a base with a flat
// interface x_n = 0.5 between them (n the last axis; meshes/block_on_base_*), two different
// elastic materials, and an exact solution whose displacement is a polynomial of degree 2 in
// each body. The exact values are prescribed on every outer face of both bodies (section
// constraints: the scenes' -bc values are constants, so the test works on the assembled
// Problem like test_order_mms.cpp); the interface is free. Newton (LU) from zero solves the
// nonlinear contact problem. At -displacement_order 2 the exact field lies in the discrete
// space and satisfies the discrete equations, so the solution must reproduce it to round-off:
// every displacement node; the displacement and its gradient at every quadrature point of
// every cell; both sides' displacements, the gap (normal and tangential, in the interface
// frame) and the traction at every interface integration point; and the contact state (stick,
// slip, open) of every point. The same scene at order 1 cannot represent the quadratic fields
// and must miss them (that is what shows the test can fail). Also checked by hand: the
// interface terms taken with the faces' vertex basis instead of their node basis fail every
// case (docs/verification.md).
//
// Which quadratic jumps an exact solution can have (stick, slip, open, and stick with a
// manufactured interface load), and how the bodies' fields are built: quad_patch_exact.hpp.
#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/mesh_points.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/reference_element.hpp"
#include "poroseam/scene.hpp"
#include "region_closure.hpp"

#include "quad_patch_exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <map>
#include <ostream>
#include <petscksp.h>
#include <string>
#include <unistd.h> // getpid: a mesh directory per test process (ctest runs them in parallel)

using namespace poroseam;
using namespace poroseam::test_support;

namespace {

PetscErrorCode setOption(const char *name, const std::string &value)
{
  return PetscOptionsSetValue(nullptr, name, value.c_str());
}

struct Case {
  const char *name;
  const char *mesh;
  double size_factor;
  const char *integration;
  Regime regime;
  bool loaded = false; ///< stick with a manufactured interface load and a quadratic jump
};

/// For gtest's messages: the case's name instead of its bytes.
void PrintTo(const Case &c, std::ostream *os)
{
  *os << c.name;
}

struct Outcome {
  double node_error = 0, node_scale = 0;     ///< max |u_h - u| and max |u| over displacement nodes
  double gap_error = 0, gap_scale = 0;       ///< at the integration points, interface frame
  double traction_error = 0;                 ///< max |t_h - t| over the points [Pa]
  double side_error = 0;                     ///< max |u_h - u| of either side at the points
  double cell_error = 0;                     ///< max |u_h - u| at the cells' quadrature points
  double strain_error = 0, strain_scale = 0; ///< max |grad u_h - grad u| there, max |grad u|
  int states[3] = {0, 0, 0}, points = 0;     ///< physics::ContactState counts
  int newton = 0, unknowns = 0;
  bool converged = false;
};

/// Gmsh's work directory of this process, where a .geo's mesh is written as <stem>.msh.
std::string meshDirectory()
{
  return testing::TempDir() + "poroseam_mesh_" + std::to_string(getpid());
}

/// Solves case c at `order` on `mesh` (a .geo, or the .msh a first solve left in
/// meshDirectory(): Gmsh then runs once per case).
PetscErrorCode solvePatch(const Case &c, int order, const Exact &ex, const std::string &mesh,
                          Outcome *out)
{
  DM dm;
  Scene scene;
  std::vector<PhysicalName> names;
  int dim;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  PetscCall(setOption("-mesh", mesh));
  PetscCall(setOption("-displacement_order", std::to_string(order)));
  PetscCall(setOption("-regions", "base,block"));
  for (const char *r : {"base", "block"}) {
    const Material &m = std::string(r) == "base" ? kBase : kBlock;
    const std::string p = std::string("-region_") + r + "_";
    PetscCall(setOption((p + "material").c_str(), "elastic"));
    PetscCall(setOption((p + "E").c_str(), std::to_string(m.young)));
    PetscCall(setOption((p + "nu").c_str(), std::to_string(m.poisson)));
  }
  PetscCall(setOption("-interfaces", "contact"));
  PetscCall(setOption("-interface_contact_side1", "base"));
  PetscCall(setOption("-interface_contact_KN", std::to_string(kNormalStiffness)));
  PetscCall(setOption("-interface_contact_KT", std::to_string(kTangentialStiffness)));
  PetscCall(setOption("-interface_contact_friction", std::to_string(kFriction)));
  PetscCall(setOption("-interface_contact_integration", c.integration));
  // Every outer face of both bodies holds every displacement component; the values set below
  // are the exact field's (the options' 0 only marks the constraints).
  std::vector<std::string> outer = {"bottom",     "top",        "base_left",
                                    "base_right", "block_left", "block_right"};
  if (ex.dim == 3)
    for (const char *f : {"base_front", "base_back", "block_front", "block_back"})
      outer.push_back(f);
  std::string list;
  for (const auto &b : outer) {
    list += (list.empty() ? "" : ",") + b;
    for (const char *comp : {"ux", "uy", "uz"}) {
      if (ex.dim == 2 && comp[1] == 'z') continue;
      PetscCall(setOption(("-bc_" + b + "_" + comp).c_str(), "0"));
    }
  }
  PetscCall(setOption("-boundaries", list));
  PetscCall(readMeshOptions(PETSC_COMM_WORLD, scene));
  PetscCall(loadGmshMesh(PETSC_COMM_SELF, scene.mesh_file, c.size_factor, meshDirectory(), &dm,
                         &names, &dim));
  PetscCheck(dim == ex.dim, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "mesh %s is %dD", c.mesh, dim);
  PetscCall(readSceneOptions(PETSC_COMM_SELF, names, dim, scene));
  PetscCall(splitInterfaces(&dm, scene));
  PetscCall(markLayoutLabels(dm, scene));
  PetscCall(createSolutionSection(dm, scene));
  Problem problem;
  PetscCall(problem.setup(dm, scene));

  // The block's points: the closure of its cells (after the split, the interface's side-2
  // copies belong to the block's cells only).
  DMLabel cellSets;
  PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
  int blockTag = 0, baseTag = 0;
  for (const auto &nm : names) {
    if (nm.name == "block") blockTag = nm.tag;
    if (nm.name == "base") baseTag = nm.tag;
  }
  PetscInt pStart, pEnd, cStart, cEnd;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  std::vector<char> inBlock;
  PetscCall(poroseam::test_support::markRegionClosure(dm, cellSets, blockTag, &inBlock));

  // The exact field at every displacement node (a node sits at the mean of its point's
  // vertices on these straight-sided cells; order 1: the vertices only).
  PetscSection s, cs;
  Vec local, exact, rate, flocal, coords, X, F, dX;
  PetscCall(DMGetLocalSection(dm, &s));
  PetscCall(DMGetCoordinateSection(dm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMCreateLocalVector(dm, &local));
  for (Vec *v : {&exact, &rate, &flocal})
    PetscCall(VecDuplicate(local, v));
  PetscCall(DMCreateGlobalVector(dm, &X));
  PetscCall(VecDuplicate(X, &F));
  PetscCall(VecDuplicate(X, &dX));
  PetscCall(VecGetSize(X, &out->unknowns));
  {
    PetscScalar *u;
    const PetscScalar *xa;
    PetscCall(VecSet(exact, 0.0));
    PetscCall(VecGetArray(exact, &u));
    PetscCall(VecGetArrayRead(coords, &xa));
    for (PetscInt pt = pStart; pt < pEnd; ++pt) {
      PetscInt dof, off;
      PetscCall(PetscSectionGetFieldDof(s, pt, kDisplacementField, &dof));
      if (!dof) continue;
      PetscCall(PetscSectionGetFieldOffset(s, pt, kDisplacementField, &off));
      double x[3];
      PetscCall(poroseam::displacementNodeLocation(dm, cs, xa, pt, dim, x));
      double ue[3];
      (inBlock[pt - pStart] ? ex.block : ex.base).value(x, ue);
      for (int k = 0; k < dim; ++k)
        u[off + k] = ue[k];
    }
    PetscCall(VecRestoreArrayRead(coords, &xa));
    PetscCall(VecRestoreArray(exact, &u));
  }
  // The manufactured interface load (stick with a quadratic jump): -int s . N_a on the nodes
  // of the side-1 faces and +int s . N_a on side 2's (the residual's interface term is -t on
  // side 1 and +t on side 2, the bodies' sigma n enter with the opposite signs), integrated
  // here with each face's own node basis (vertex basis at order 1) and degree-4 rule (exact
  // for s N_a on these flat faces), not through the interface assembly. A face's reference node is
  // matched by position to the mesh point that carries it.
  Vec load = nullptr;
  if (ex.loaded) {
    PetscCall(VecDuplicate(local, &load));
    PetscCall(VecSet(load, 0.0));
    PetscScalar *b;
    const PetscScalar *xa;
    PetscCall(VecGetArray(load, &b));
    PetscCall(VecGetArrayRead(coords, &xa));
    std::map<int, ReferenceElement> faces;
    std::vector<PetscInt> verts;
    for (PetscInt cell = cStart; cell < cEnd; ++cell) {
      DMPolytopeType ct;
      PetscCall(DMPlexGetCellType(dm, cell, &ct));
      if (ct != DM_POLYTOPE_SEG_PRISM_TENSOR && ct != DM_POLYTOPE_TRI_PRISM_TENSOR &&
          ct != DM_POLYTOPE_QUAD_PRISM_TENSOR)
        continue;
      const PetscInt *cone;
      PetscCall(DMPlexGetCone(dm, cell, &cone));
      for (int side = 0; side < 2; ++side) {
        const PetscInt face = cone[side];
        const double sign = inBlock[face - pStart] ? 1.0 : -1.0;
        DMPolytopeType ft;
        PetscCall(DMPlexGetCellType(dm, face, &ft));
        if (!faces.count((int)ft)) PetscCall(ReferenceElement::create(ft, &faces[(int)ft], 2));
        const ReferenceElement &e = faces[(int)ft];
        // Order 1: the vertex basis with the same (degree-4) rule.
        const int nv = e.num_vertices, nn = order == 1 ? nv : e.num_nodes, ed = e.dim;
        const double *N = order == 1 ? e.basis.data() : e.node_basis.data();
        const double *node_coords = order == 1 ? e.vertex_coords.data() : e.node_coords.data();
        PetscCall(closureVertices(dm, face, verts));
        PetscCheck((int)verts.size() == nv, PETSC_COMM_SELF, PETSC_ERR_PLIB, "face %d", (int)face);
        std::vector<double> X(nv * dim), phi(nv);
        for (int v = 0; v < nv; ++v) {
          PetscInt xo;
          PetscCall(PetscSectionGetOffset(cs, verts[v], &xo));
          for (int d = 0; d < dim; ++d)
            X[v * dim + d] = xa[xo + d];
        }
        std::vector<PetscInt> offset(nn, -1);
        PetscInt np, *pts = nullptr;
        PetscCall(DMPlexGetTransitiveClosure(dm, face, PETSC_TRUE, &np, &pts));
        for (int a = 0; a < nn; ++a) {
          double xn[3] = {0, 0, 0};
          e.evaluate(&node_coords[a * ed], phi.data(), nullptr);
          for (int v = 0; v < nv; ++v)
            for (int d = 0; d < dim; ++d)
              xn[d] += phi[v] * X[v * dim + d];
          for (PetscInt k = 0; k < np; ++k) {
            PetscInt dof;
            PetscCall(PetscSectionGetFieldDof(s, pts[2 * k], kDisplacementField, &dof));
            if (!dof) continue;
            double xp[3] = {0, 0, 0}, dist = 0.0;
            PetscCall(displacementNodeLocation(dm, cs, xa, pts[2 * k], dim, xp));
            for (int d = 0; d < dim; ++d)
              dist += std::fabs(xp[d] - xn[d]);
            if (dist < 1e-9)
              PetscCall(PetscSectionGetFieldOffset(s, pts[2 * k], kDisplacementField, &offset[a]));
          }
          PetscCheck(offset[a] >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                     "node %d of face %d carries no displacement", a, (int)face);
        }
        PetscCall(DMPlexRestoreTransitiveClosure(dm, face, PETSC_TRUE, &np, &pts));
        for (int q = 0; q < e.num_quadrature; ++q) {
          double xq[3] = {0, 0, 0}, J[3][2] = {{0}}, xi[3] = {0, 0, 0};
          for (int v = 0; v < nv; ++v)
            for (int d = 0; d < dim; ++d) {
              xq[d] += e.basis[q * nv + v] * X[v * dim + d];
              for (int r = 0; r < ed; ++r)
                J[d][r] += X[v * dim + d] * e.basis_derivatives[(q * nv + v) * ed + r];
            }
          double measure;
          if (ed == 1)
            measure = std::hypot(J[0][0], J[1][0], J[2][0]);
          else
            measure = std::hypot(J[1][0] * J[2][1] - J[2][0] * J[1][1],
                                 J[2][0] * J[0][1] - J[0][0] * J[2][1],
                                 J[0][0] * J[1][1] - J[1][0] * J[0][1]);
          for (int r = 0; r < dim - 1; ++r)
            xi[r] = xq[r] - kCentre;
          const double w = e.quadrature_weights[q] * measure;
          for (int a = 0; a < nn; ++a)
            for (int i = 0; i < dim; ++i)
              b[offset[a] + i] += sign * w * N[q * nn + a] * ex.interface_load.value(dim, i, xi);
        }
      }
    }
    PetscCall(VecRestoreArrayRead(coords, &xa));
    PetscCall(VecRestoreArray(load, &b));
  }
  // Newton from zero inside: the constrained entries of the local vector keep the exact
  // values (the global vector does not hold them).
  PetscCall(VecCopy(exact, local));
  PetscCall(VecSet(X, 0.0));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
  PetscCall(VecSet(rate, 0.0));
  const ResidualMode mode{1.0, true, 0.0};
  Mat J;
  KSP ksp;
  PC pc;
  PetscCall(DMCreateMatrix(dm, &J));
  PetscCall(KSPCreate(PETSC_COMM_SELF, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  double uscale;
  PetscCall(VecNorm(exact, NORM_INFINITY, &uscale));
  for (out->newton = 1; out->newton <= 25; ++out->newton) {
    PetscCall(problem.residual(0.0, local, rate, mode, flocal));
    if (load) PetscCall(VecAXPY(flocal, -1.0, load));
    PetscCall(VecSet(F, 0.0));
    PetscCall(DMLocalToGlobal(dm, flocal, ADD_VALUES, F));
    PetscCall(problem.jacobian(0.0, 0.0, local, rate, mode, J));
    PetscCall(KSPSetOperators(ksp, J, J));
    PetscCall(KSPSolve(ksp, F, dX));
    PetscCall(VecAXPY(X, -1.0, dX));
    PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
    double step;
    PetscCall(VecNorm(dX, NORM_INFINITY, &step));
    if (step <= 1e-13 * uscale) {
      out->converged = true;
      break;
    }
  }

  // Every displacement node against the exact field.
  {
    Vec diff;
    PetscCall(VecDuplicate(local, &diff));
    PetscCall(VecWAXPY(diff, -1.0, exact, local));
    PetscCall(VecNorm(diff, NORM_INFINITY, &out->node_error));
    out->node_scale = uscale;
    PetscCall(VecDestroy(&diff));
  }
  // The field between the nodes: displacement and gradient at the quadrature points of every
  // bulk cell (the order-2 element's rule, degree 4, at both orders), from the closure by the
  // node basis (order 2) or the vertex basis (order 1).
  {
    std::map<int, ReferenceElement> elements;
    PointGeometry g;
    for (PetscInt cell = cStart; cell < cEnd; ++cell) {
      PetscInt tag;
      PetscCall(DMLabelGetValue(cellSets, cell, &tag));
      if (tag != blockTag && tag != baseTag) continue; // the interface's cohesive cells
      const BodyField &body = tag == blockTag ? ex.block : ex.base;
      DMPolytopeType ct;
      PetscCall(DMPlexGetCellType(dm, cell, &ct));
      if (!elements.count((int)ct)) PetscCall(ReferenceElement::create(ct, &elements[(int)ct], 2));
      const ReferenceElement &e = elements[(int)ct];
      PetscScalar *xc = nullptr, *xu = nullptr;
      PetscInt nc = 0, nu = 0;
      PetscCall(DMPlexVecGetClosure(dm, cs, coords, cell, &nc, &xc));
      PetscCall(DMPlexVecGetClosure(dm, s, local, cell, &nu, &xu));
      const int nn = order == 1 ? e.num_vertices : e.num_nodes;
      PetscCheck(nu == nn * dim, PETSC_COMM_SELF, PETSC_ERR_PLIB, "closure of cell %d: %d values",
                 (int)cell, (int)nu);
      for (int q = 0; q < e.num_quadrature; ++q) {
        PetscCheck(mapQuadraturePoint(e, xc, q, g) > 0.0, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                   "inverted cell %d", (int)cell);
        const double *N = order == 1 ? g.phi : g.node_phi;
        const double *dN = order == 1 ? g.grad_phi : g.grad_node_phi;
        double ue[3], ge[3][3];
        body.value(g.x, ue);
        body.gradient(g.x, ge);
        for (int i = 0; i < dim; ++i) {
          double uh = 0.0, gh[3] = {0, 0, 0};
          for (int a = 0; a < nn; ++a) {
            uh += N[a] * xu[a * dim + i];
            for (int j = 0; j < dim; ++j)
              gh[j] += dN[a * dim + j] * xu[a * dim + i];
          }
          out->cell_error = std::max(out->cell_error, std::fabs(uh - ue[i]));
          for (int j = 0; j < dim; ++j) {
            out->strain_error = std::max(out->strain_error, std::fabs(gh[j] - ge[i][j]));
            out->strain_scale = std::max(out->strain_scale, std::fabs(ge[i][j]));
          }
        }
      }
      PetscCall(DMPlexVecRestoreClosure(dm, s, local, cell, &nu, &xu));
      PetscCall(DMPlexVecRestoreClosure(dm, cs, coords, cell, &nc, &xc));
    }
  }
  // The gap (interface frame) and the traction at every integration point.
  const int n = dim - 1;
  PetscCall(problem.interfaces().visit(
      local, InterfaceRates{}, [&](int, int, PetscInt, const InterfacePointState &st) {
        double ub[3], ua[3], jump[3] = {0, 0, 0}, exact_gap[3] = {0, 0, 0}, xi[3] = {0, 0, 0};
        ex.block.value(st.x, ub);
        ex.base.value(st.x, ua);
        for (int k = 0; k < dim; ++k)
          jump[k] = ub[k] - ua[k];
        for (int i = 0; i < dim; ++i)
          for (int k = 0; k < dim; ++k)
            exact_gap[i] += st.frame[i][k] * jump[k];
        const double got[3] = {st.gap_normal, st.gap_tangential[0], st.gap_tangential[1]};
        for (int k = 0; k < dim; ++k)
          out->side_error = std::max({out->side_error, std::fabs(st.displacement1[k] - ua[k]),
                                      std::fabs(st.displacement2[k] - ub[k])});
        for (int i = 0; i < dim; ++i) {
          out->gap_error = std::max(out->gap_error, std::fabs(got[i] - exact_gap[i]));
          out->gap_scale = std::max(out->gap_scale, std::fabs(exact_gap[i]));
        }
        // The traction on side 1 (the base) from side 2: sigma n (n from base to block), plus
        // the manufactured load where there is one (K [u] in stick).
        for (int t = 0; t < n; ++t)
          xi[t] = st.x[t] - kCentre;
        for (int i = 0; i < dim; ++i)
          out->traction_error = std::max(out->traction_error,
                                         std::fabs(st.traction[i] - ex.traction.value(dim, i, xi) -
                                                   ex.interface_load.value(dim, i, xi)));
        ++out->states[(int)st.response.state];
        ++out->points;
      }));

  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&J));
  for (Vec *v : {&local, &exact, &rate, &flocal, &X, &F, &dX, &load})
    PetscCall(VecDestroy(v));
  PetscCall(problem.release());
  PetscCall(DMDestroy(&dm));
  PetscCall(PetscOptionsClear(nullptr));
  PetscFunctionReturn(0);
}

const char *regimeName(Regime r)
{
  return r == Regime::stick ? "stick" : r == Regime::slip ? "slip" : "open";
}

} // namespace

class QuadJumpPatch : public ::testing::TestWithParam<Case> {};

TEST_P(QuadJumpPatch, Order2ExactOrder1Not)
{
  const Case c = GetParam();
  const int dim = std::string(c.mesh).find("_3d") != std::string::npos ? 3 : 2;
  const Exact ex = exactSolution(dim, c.regime, c.loaded);
  const double defect = constructionDefect(ex);
  std::printf("%s: exact field's own defect (div sigma, sigma n - t) %.1e of 1e5 Pa\n", c.name,
              defect);
  ASSERT_LT(defect, 1e-12) << "the exact solution is not one";
  const double traction_scale = 1e5;
  Outcome o[3];
  const std::string geo = std::string(POROSEAM_SOURCE_DIR) + "/meshes/" + c.mesh;
  const std::string msh = meshDirectory() + "/" +
                          std::string(c.mesh).substr(0, std::string(c.mesh).size() - 4) + ".msh";
  for (int order : {2, 1}) {
    ASSERT_EQ(solvePatch(c, order, ex, order == 2 ? geo : msh, &o[order]), 0);
    const Outcome &r = o[order];
    std::printf("%s order %d: %d unknowns, Newton %d%s; max |u_h - u| / max |u| at the nodes "
                "%.2e, the cells' points %.2e, the interface points %.2e; max |grad (u_h - u)| / "
                "max |grad u| %.2e; gaps %.2e; traction max |t_h - t| / 1e5 Pa = %.2e; open %d, "
                "stick %d, slip %d of %d points\n",
                c.name, order, r.unknowns, r.newton, r.converged ? "" : " (not converged)",
                r.node_error / r.node_scale, r.cell_error / r.node_scale,
                r.side_error / r.node_scale, r.strain_error / r.strain_scale,
                r.gap_error / r.gap_scale, r.traction_error / traction_scale, r.states[0],
                r.states[1], r.states[2], r.points);
  }
  const Outcome &q = o[2], &l = o[1];
  ASSERT_TRUE(q.converged);
  ASSERT_GT(q.points, 0);
  EXPECT_EQ(q.states[(int)c.regime], q.points)
      << "not every point is in the " << regimeName(c.regime) << " state";
  EXPECT_LT(q.node_error / q.node_scale, 1e-9);
  EXPECT_LT(q.side_error / q.node_scale, 1e-9);
  EXPECT_LT(q.cell_error / q.node_scale, 1e-9);
  EXPECT_LT(q.strain_error / q.strain_scale, 1e-9);
  EXPECT_LT(q.gap_error / q.gap_scale, 1e-9);
  EXPECT_LT(q.traction_error / traction_scale, 1e-9);
  // Order 1: the same scene; linear elements cannot hold the quadratic fields between the
  // nodes. (Their nodal values can be exact on these uniform meshes: the linear elements'
  // stencil there is exact for quadratics without body force, a nodal superconvergence; and
  // in stick the jump is linear. So the field is compared inside the cells as well.)
  EXPECT_GT(std::max({l.node_error / l.node_scale, l.cell_error / l.node_scale,
                      l.strain_error / l.strain_scale, l.gap_error / l.gap_scale}),
            1e-4)
      << "order 1 reproduced the quadratic solution: the test would not see a wrong order 2";
}

// Each regime on quadrilaterals / hexahedra and triangles / tetrahedra; both rules where the
// faces have them (nodal Simpson: segments and quadrilaterals only). Simpson integrates the
// interface terms exactly here: the traction is linear, times a quadratic test function.
INSTANTIATE_TEST_SUITE_P(
    Interfaces, QuadJumpPatch,
    ::testing::Values(
        Case{"stick2d_quad", "block_on_base_2d.geo", 1.0, "gauss", Regime::stick},
        Case{"slip2d_quad_nodal", "block_on_base_2d.geo", 1.0, "nodal", Regime::slip},
        Case{"open2d_quad", "block_on_base_2d.geo", 1.0, "gauss", Regime::open},
        Case{"stick2d_tri_nodal", "block_on_base_2d_tri.geo", 1.0, "nodal", Regime::stick},
        Case{"slip2d_tri", "block_on_base_2d_tri.geo", 1.0, "gauss", Regime::slip},
        Case{"stick3d_hex_nodal", "block_on_base_3d.geo", 1.5, "nodal", Regime::stick},
        Case{"slip3d_hex", "block_on_base_3d.geo", 1.5, "gauss", Regime::slip},
        Case{"stick3d_tet", "block_on_base_3d_tet.geo", 1.5, "gauss", Regime::stick},
        Case{"slip3d_tet", "block_on_base_3d_tet.geo", 1.5, "gauss", Regime::slip},
        Case{"open3d_tet", "block_on_base_3d_tet.geo", 1.5, "gauss", Regime::open},
        // Stick with a quadratic jump, held by a manufactured interface load (Gauss only: the
        // nodal rule is not exact for the quadratic traction K [u] times a quadratic).
        Case{"stick2d_quad_loaded", "block_on_base_2d.geo", 1.0, "gauss", Regime::stick, true},
        Case{"stick3d_hex_loaded", "block_on_base_3d.geo", 1.5, "gauss", Regime::stick, true},
        Case{"stick3d_tet_loaded", "block_on_base_3d_tet.geo", 1.5, "gauss", Regime::stick, true}),
    [](const auto &info) { return std::string(info.param.name); });
