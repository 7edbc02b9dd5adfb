#pragma once
// Test helper: the problem of the options in the database, set up as a run does it (meshed by
// gmsh, split into cohesive cells, laid out), with the work vectors and the dense comparison of
// the assembled Jacobian with central finite differences that the Jacobian tests on meshed
// scenes share (test_interface_jacobian, test_interface_flow_jacobian, test_quad_interface,
// test_curved_jacobian); and the options of the block pressed on a base through a contact
// interface (meshes/block_on_base*.geo, block_on_arc_2d.geo). Serial.
#include "central_differences.hpp"
#include "region_closure.hpp"

#include "poroseam/interfaces.hpp"
#include "poroseam/layout.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/problem.hpp"
#include "poroseam/scene.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h> // getpid: a mesh directory per test process (ctest runs them in parallel)
#include <vector>

namespace poroseam::test_support {

inline PetscErrorCode setOption(const char *name, const std::string &value)
{
  return PetscOptionsSetValue(nullptr, name, value.c_str());
}

/// Clears the options, then sets those of the block-on-base scenes: the mesh (in meshes/), the
/// regions base and block (E = 1e8 Pa, nu = 0.25; porous: biot with k = 1e-11 m2, n = 0.4,
/// rho_s = 2650 kg/m3; otherwise elastic) and the contact interface between them (side 1 the
/// base, K_N = 1e10, K_T = 5e9 Pa/m, friction 0.5). Each test adds its own.
inline PetscErrorCode setBlockOnBaseOptions(const char *mesh, bool porous)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  const std::string src = POROSEAM_SOURCE_DIR;
  PetscCall(setOption("-mesh", src + "/meshes/" + mesh));
  PetscCall(setOption("-regions", "base,block"));
  for (const char *r : {"base", "block"}) {
    const std::string p = std::string("-region_") + r + "_";
    PetscCall(setOption((p + "material").c_str(), porous ? "biot" : "elastic"));
    PetscCall(setOption((p + "E").c_str(), "1e8"));
    PetscCall(setOption((p + "nu").c_str(), "0.25"));
    if (!porous) continue;
    PetscCall(setOption((p + "permeability").c_str(), "1e-11"));
    PetscCall(setOption((p + "porosity").c_str(), "0.4"));
    PetscCall(setOption((p + "rho_s").c_str(), "2650"));
  }
  PetscCall(setOption("-interfaces", "contact"));
  PetscCall(setOption("-interface_contact_side1", "base"));
  PetscCall(setOption("-interface_contact_KN", "1e10"));
  PetscCall(setOption("-interface_contact_KT", "5e9"));
  PetscCall(setOption("-interface_contact_friction", "0.5"));
  PetscFunctionReturn(0);
}

/// The problem of the options in the database, and its work vectors.
struct MeshedProblem {
  DM dm = nullptr;
  Scene scene;
  std::vector<PhysicalName> names;
  int dim = 0;
  Problem problem;
  Vec local = nullptr, rate = nullptr, previous = nullptr, flocal = nullptr; ///< local layout
  Vec X = nullptr, Fp = nullptr, Fm = nullptr;                               ///< global layout

  /// Meshes the scene's mesh at `size_factor` (at its -mesh_geometry_order), reads the scene,
  /// splits the interfaces, lays out the fields, sets the problem up; creates the vectors.
  PetscErrorCode create(double size_factor)
  {
    PetscFunctionBeginUser;
    PetscCall(readMeshOptions(PETSC_COMM_WORLD, scene));
    PetscCall(loadGmshMesh(PETSC_COMM_SELF, scene.mesh_file, size_factor,
                           testing::TempDir() + "poroseam_mesh_" + std::to_string(getpid()), &dm,
                           &names, &dim, scene.mesh_geometry_order));
    PetscCall(readSceneOptions(PETSC_COMM_SELF, names, dim, scene));
    PetscCall(splitInterfaces(&dm, scene));
    PetscCall(markLayoutLabels(dm, scene));
    PetscCall(createSolutionSection(dm, scene));
    PetscCall(problem.setup(dm, scene));
    PetscCall(DMCreateLocalVector(dm, &local));
    for (Vec *v : {&rate, &previous, &flocal})
      PetscCall(VecDuplicate(local, v));
    PetscCall(DMCreateGlobalVector(dm, &X));
    PetscCall(VecDuplicate(X, &Fp));
    PetscCall(VecDuplicate(X, &Fm));
    PetscFunctionReturn(0);
  }

  /// in[p - pStart] = 1 for every point of the closure of the cells of the physical group
  /// `region` (markRegionClosure).
  PetscErrorCode markRegion(const char *region, std::vector<char> *in) const
  {
    DMLabel cellSets;
    PetscFunctionBeginUser;
    PetscCall(DMGetLabel(dm, "Cell Sets", &cellSets));
    int tag = 0;
    for (const auto &n : names)
      if (n.name == region) tag = n.tag;
    PetscCall(markRegionClosure(dm, cellSets, tag, in));
    PetscFunctionReturn(0);
  }

  /// field[i] of every global dof i, from the field of every local one.
  PetscErrorCode globalFields(const std::vector<int> &field_of_local, std::vector<int> *field) const
  {
    Vec marker, g;
    PetscScalar *m;
    const PetscScalar *gm;
    PetscInt n;
    PetscFunctionBeginUser;
    PetscCall(VecGetLocalSize(X, &n));
    field->assign(n, 0);
    PetscCall(VecDuplicate(local, &marker));
    PetscCall(VecGetArray(marker, &m));
    for (size_t i = 0; i < field_of_local.size(); ++i)
      m[i] = field_of_local[i];
    PetscCall(VecRestoreArray(marker, &m));
    PetscCall(DMGetGlobalVector(dm, &g));
    PetscCall(DMLocalToGlobal(dm, marker, INSERT_VALUES, g));
    PetscCall(VecGetArrayRead(g, &gm));
    for (PetscInt i = 0; i < n; ++i)
      (*field)[i] = (int)std::lround(gm[i]);
    PetscCall(VecRestoreArrayRead(g, &gm));
    PetscCall(DMRestoreGlobalVector(dm, &g));
    PetscCall(VecDestroy(&marker));
    PetscFunctionReturn(0);
  }

  /// rate = a (local - previous) / dt, given as `scale` = a / dt: the rates of a backward Euler
  /// (a = 1) or BDF2 (a = 1.5, previous the history combination) step.
  PetscErrorCode ratesFromPrevious(double scale)
  {
    PetscFunctionBeginUser;
    PetscCall(VecWAXPY(rate, -1.0, previous, local));
    PetscCall(VecScale(rate, scale));
    PetscFunctionReturn(0);
  }

  /// The global residual at Xg into Fg: Xg to `local`, `rates()` (which may set `rate` from
  /// `local`), the problem's residual at time t, added into Fg.
  template <class Rates>
  PetscErrorCode residual(Vec Xg, Vec Fg, double t, const ResidualMode &mode, Rates &&rates)
  {
    PetscFunctionBeginUser;
    PetscCall(DMGlobalToLocal(dm, Xg, INSERT_VALUES, local));
    PetscCall(rates());
    PetscCall(problem.residual(t, local, rate, mode, flocal));
    PetscCall(VecSet(Fg, 0.0));
    PetscCall(DMLocalToGlobal(dm, flocal, ADD_VALUES, Fg));
    PetscFunctionReturn(0);
  }

  /// The Jacobian at X (to `local`, then `rates()`; the problem's Jacobian at time t with the
  /// rates' `shift`), made dense, against central differences of `residual` at X with steps
  /// `step(j)`: visit(i, j, fd, J_ij) for every pair of global dofs.
  template <class Rates, class Step, class Visit>
  PetscErrorCode compareWithDifferences(double t, double shift, const ResidualMode &mode,
                                        Rates &&rates, Step &&step, Visit &&visit)
  {
    Mat J, Jd;
    const PetscScalar *jd;
    PetscInt n;
    PetscFunctionBeginUser;
    PetscCall(VecGetLocalSize(X, &n));
    PetscCall(DMCreateMatrix(dm, &J));
    PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, local));
    PetscCall(rates());
    PetscCall(problem.jacobian(t, shift, local, rate, mode, J));
    PetscCall(MatConvert(J, MATDENSE, MAT_INITIAL_MATRIX, &Jd));
    PetscCall(MatDenseGetArrayRead(Jd, &jd));
    PetscCall(centralDifferences(
        X, Fp, Fm, [&](Vec Xg, Vec Fg) { return residual(Xg, Fg, t, mode, rates); }, step,
        [&](PetscInt i, PetscInt j, double fd) {
          visit(i, j, fd, jd[i + j * n]); // column-major
        }));
    PetscCall(MatDenseRestoreArrayRead(Jd, &jd));
    PetscCall(MatDestroy(&Jd));
    PetscCall(MatDestroy(&J));
    PetscFunctionReturn(0);
  }

  /// compareWithDifferences by blocks of fields: for the global dofs i, j of fields field[i],
  /// field[j], the largest |J_ij - J_fd,ij| and |J_fd,ij| into max_error and max_entry (the
  /// mass rows are many orders smaller than the force rows: one norm would hide them).
  template <class Rates, class Step, size_t NF>
  PetscErrorCode compareBlocks(double t, double shift, const ResidualMode &mode, Rates &&rates,
                               Step &&step, const std::vector<int> &field,
                               double (&max_error)[NF][NF], double (&max_entry)[NF][NF])
  {
    PetscFunctionBeginUser;
    PetscCall(compareWithDifferences(t, shift, mode, rates, step,
                                     [&](PetscInt i, PetscInt j, double fd, double jij) {
                                       double &err = max_error[field[i]][field[j]];
                                       double &ref = max_entry[field[i]][field[j]];
                                       err = std::max(err, std::fabs(fd - jij));
                                       ref = std::max(ref, std::fabs(fd));
                                     }));
    PetscFunctionReturn(0);
  }

  /// Destroys the vectors, releases the problem, destroys the DM and clears the options.
  PetscErrorCode destroy()
  {
    PetscFunctionBeginUser;
    for (Vec *v : {&local, &rate, &previous, &flocal, &X, &Fp, &Fm})
      PetscCall(VecDestroy(v));
    PetscCall(problem.release());
    PetscCall(DMDestroy(&dm));
    PetscCall(PetscOptionsClear(nullptr));
    PetscFunctionReturn(0);
  }
};

} // namespace poroseam::test_support
