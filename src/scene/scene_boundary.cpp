// A boundary's options: its conditions (prescribed displacements and pore pressure, loads,
// fluxes, with time functions) and the physical group a name of -boundaries stands for, each
// checked with a message naming the option. Part of readSceneOptions (scene.cpp), in the
// boundary's -help section; apart like scene_region.cpp and scene_interface.cpp.
#include "scene_parts.hpp"

#include "poroseam/option_check.hpp"
#include "poroseam/scene_options.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <petscsys.h>
#include <set>
#include <sstream>
#include <utility>

namespace poroseam {

/// A name of -boundaries: a face group (dimension dim - 1), else a physical point (dimension
/// 0) or, in 3D, a physical curve (dimension 1): supports, prescribed displacements only.
PetscErrorCode findBoundaryGroup(MPI_Comm comm, const std::vector<PhysicalName> &names, int dim,
                                 const std::string &name, Boundary *b)
{
  PetscFunctionBeginUser;
  for (int d : {dim - 1, 0, 1})
    for (const auto &n : names)
      if (n.dim == d && n.name == name && d < dim) {
        b->tag = n.tag;
        b->support_dim = d == dim - 1 ? -1 : d;
        PetscFunctionReturn(0);
      }
  SETERRQ(comm, PETSC_ERR_USER_INPUT,
          "-boundaries: boundary '%s' is not a physical group of dimension %d in the mesh, "
          "nor a physical point%s; the mesh has: %s (physical points: %s%s%s)",
          name.c_str(), dim - 1, dim == 3 ? " or curve" : "", joinNames(names, dim - 1).c_str(),
          joinNames(names, 0).c_str(), dim == 3 ? "; curves: " : "",
          dim == 3 ? joinNames(names, 1).c_str() : "");
}

namespace {

/// A condition's time function (-bc_<b>_<q>_ramp or _table), in the boundary's section.
PetscErrorCode readTimeFunction(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                                const std::string &option, TimeFunction &f)
{
  double ramp = 0.0;
  bool ramp_set = false, table_set = false;
  std::string table;
  PetscFunctionBeginUser;
  PetscCall(getReal(PetscOptionsObject, option + "_ramp",
                    "ramp time T [s]: " + option +
                        " grows linearly from 0 at t = 0 to its value at T (none: at once)",
                    &ramp, &ramp_set, "none"));
  PetscCall(getString(PetscOptionsObject, option + "_table",
                      "CSV file time,factor: " + option + " times the interpolated factor", table,
                      &table_set));
  PetscCheck(!(ramp_set && table_set), comm, PETSC_ERR_USER_INPUT,
             "%s: give either %s_ramp or %s_table, not both", option.c_str(), option.c_str(),
             option.c_str());
  if (ramp_set) {
    PetscCheck(ramp > 0.0, comm, PETSC_ERR_USER_INPUT, "%s_ramp = %g: ramp time must be > 0",
               option.c_str(), ramp);
    f = TimeFunction::ramp(ramp);
  } else if (table_set) {
    std::vector<double> t, v;
    const std::string err = readTimeTable(table, t, v);
    PetscCheck(err.empty(), comm, PETSC_ERR_USER_INPUT, "%s_table: %s", option.c_str(),
               err.c_str());
    // Before its first row a table would hold its first factor (OpenGeoSys' curves do),
    // which for a table starting at t = 5 s applies the load from t = 0 on: most likely
    // not what was meant (a load that starts at 5 s). The run starts at t = 0: the table
    // must say what holds from then on.
    PetscCheck(t.front() <= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%s_table: time table '%s' starts at t = %s s, after the start of the run "
               "(t = 0): its factor before t = %s s is not given; add a first row "
               "'0,<factor>' (the factor is interpolated linearly between rows)",
               option.c_str(), table.c_str(), number(t.front()).c_str(), number(t.front()).c_str());
    f = TimeFunction::table(t, v);
  }
  PetscFunctionReturn(0);
}

} // namespace

/// A boundary's conditions, in its own -help section (PetscOptionsBegin in readSceneOptions).
PetscErrorCode readBoundary(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const Scene &scene,
                            const Boundary &b, std::vector<BoundaryCondition> &out)
{
  const std::string p = "-bc_" + b.name + "_";
  const char *comps[3] = {key(BoundaryKey::ux), key(BoundaryKey::uy), key(BoundaryKey::uz)};
  PetscFunctionBeginUser;
  // One condition of this boundary, defined by the option p + q.
  auto add = [&](BcKind kind, const char *q, std::vector<double> value,
                 int component) -> PetscErrorCode {
    PetscFunctionBeginUser;
    BoundaryCondition bc;
    bc.kind = kind;
    bc.component = component;
    bc.value = std::move(value);
    bc.option = p + q;
    bc.boundary = b.name;
    bc.tag = b.tag;
    bc.support_dim = b.support_dim;
    PetscCall(readTimeFunction(PetscOptionsObject, comm, bc.option, bc.time));
    out.push_back(bc);
    PetscFunctionReturn(0);
  };
  // A condition that cannot apply here (uz in 2D, p without pressure unknowns) is not listed
  // by -help; given anyway, it is refused below.
  auto condition = [&](const char *q, const std::string &help, bool applies, double *v,
                       bool *set) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (applies) {
      PetscCall(getReal(PetscOptionsObject, p + q, help, v, set, "none"));
    } else {
      PetscBool given = PETSC_FALSE;
      PetscCall(PetscOptionsHasName(nullptr, nullptr, (p + q).c_str(), &given));
      *set = given;
    }
    PetscFunctionReturn(0);
  };
  for (int c = 0; c < 3; ++c) {
    double v = 0.0;
    bool set = false;
    PetscCall(condition(comps[c],
                        std::string("prescribed displacement component ") + "xyz"[c] + " [m]",
                        c < scene.dim, &v, &set));
    if (!set) continue;
    PetscCheck(c < scene.dim, comm, PETSC_ERR_USER_INPUT,
               "%s%s: the mesh is %dD, it has no %s component", p.c_str(), comps[c], scene.dim,
               comps[c]);
    PetscCall(add(BcKind::displacement, comps[c], {v}, c));
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition(key(BoundaryKey::p),
                        "prescribed pore pressure [Pa] (absolute: hydrostatic included)",
                        scene.hasPressure(), &v, &set));
    if (set) {
      PetscCheck(scene.hasPressure(), comm, PETSC_ERR_USER_INPUT,
                 "%sp: the scene has no pressure unknowns (drained, or no biot region)", p.c_str());
      PetscCall(add(BcKind::pressure, key(BoundaryKey::p), {v}, 0));
    }
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition(key(BoundaryKey::p3),
                        "prescribed interface pressure p3 [Pa] where an interface with flow "
                        "meets the boundary",
                        scene.hasInterfacePressure(), &v, &set));
    if (set) {
      PetscCheck(scene.hasInterfacePressure(), comm, PETSC_ERR_USER_INPUT,
                 "%sp3: no interface of the scene has flow (-interface_<i>_flow)", p.c_str());
      PetscCall(add(BcKind::interface_pressure, key(BoundaryKey::p3), {v}, 0));
    }
  }
  {
    std::vector<double> v;
    bool set = false;
    PetscCall(getRealList(PetscOptionsObject, p + key(BoundaryKey::traction),
                          "applied traction [Pa], " + std::to_string(scene.dim) +
                              " comma-separated components (tension positive: sigma n)",
                          v, &set));
    if (set) {
      PetscCheck((int)v.size() == scene.dim, comm, PETSC_ERR_USER_INPUT,
                 "%straction: expected %d comma-separated components, got %d", p.c_str(), scene.dim,
                 (int)v.size());
      // A prescribed displacement component replaces the equilibrium row the traction's
      // component would load: a non-zero one would be dropped without a word. (A zero
      // component is the free reaction of that prescribed component: accepted.)
      for (const auto &c : out)
        PetscCheck(
            !(c.boundary == b.name && c.kind == BcKind::displacement && v[c.component] != 0.0),
            comm, PETSC_ERR_USER_INPUT,
            "%s and %straction on the same boundary '%s': the prescribed displacement "
            "%s leaves no %c traction to apply (component %d of %straction is %s, not 0); "
            "give one of them (or split the boundary in the mesh)",
            c.option.c_str(), p.c_str(), b.name.c_str(), comps[c.component], "xyz"[c.component],
            c.component + 1, p.c_str(), number(v[c.component]).c_str());
      PetscCall(add(BcKind::traction, key(BoundaryKey::traction), v, 0));
    }
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition(key(BoundaryKey::pressure),
                        "normal pressure P [Pa] on the faces, t = -P n (positive pushes into "
                        "the body; not the pore pressure, -bc_<b>_p)",
                        true, &v, &set));
    if (set) {
      // Both load the same faces' equilibrium rows: one of them is the load meant.
      for (const auto &c : out)
        PetscCheck(!(c.boundary == b.name && c.kind == BcKind::traction), comm,
                   PETSC_ERR_USER_INPUT,
                   "%spressure and %straction on the same boundary '%s': give the load as one "
                   "of them (a pressure is the traction -P n), or split the boundary in the mesh",
                   p.c_str(), p.c_str(), b.name.c_str());
      PetscCall(add(BcKind::normal_pressure, key(BoundaryKey::pressure), {v}, 0));
    }
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition(key(BoundaryKey::flux),
                        "outward Darcy flux q.n [m/s] (positive: water leaves)",
                        scene.hasPressure(), &v, &set));
    if (set) {
      PetscCheck(scene.hasPressure(), comm, PETSC_ERR_USER_INPUT,
                 "%sflux: the scene has no pressure unknowns (drained, or no biot region)",
                 p.c_str());
      // A prescribed pressure fixes the water at the boundary: a flux there would be ignored.
      const bool pressure = std::any_of(out.begin(), out.end(), [&](const BoundaryCondition &c) {
        return c.boundary == b.name && c.kind == BcKind::pressure;
      });
      PetscCheck(!pressure, comm, PETSC_ERR_USER_INPUT,
                 "%sflux and %sp on the same boundary '%s': a prescribed pressure leaves no "
                 "flux to prescribe; give one of them (or split the boundary in the mesh)",
                 p.c_str(), p.c_str(), b.name.c_str());
      PetscCall(add(BcKind::flux, key(BoundaryKey::flux), {v}, 0));
    }
  }
  // A physical point or curve is a support: it holds displacements, it takes no load (a load
  // on a point or a line of a 3D body is of infinite pressure: the displacement beneath it is
  // unbounded).
  const char *support = b.support_dim == 0 ? "point" : "curve";
  for (const auto &c : out)
    PetscCheck(!(c.boundary == b.name && b.support_dim >= 0 && c.kind != BcKind::displacement),
               comm, PETSC_ERR_USER_INPUT,
               "%s: '%s' is a physical %s; a %s group carries prescribed displacements only "
               "(%sux, _uy%s), a support that removes a rigid-body mode; loads, pressures and "
               "fluxes need a face group",
               c.option.c_str(), b.name.c_str(), support, support, p.c_str(),
               scene.dim == 3 ? ", _uz" : "");
  PetscFunctionReturn(0);
}

} // namespace poroseam
