#include "poroseam/scene.hpp"

#include "poroseam/option_check.hpp"
#include "poroseam/scene_options.hpp"
#include "scene_parts.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <petscsys.h>
#include <set>
#include <sstream>

namespace poroseam {
namespace {

/// A number as %g writes it (PETSc's own %g in messages adds a trailing dot: "5.").
std::string number(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

/// The meaningful range of -stabilization_factor F around the optimal 1/4 (docs/physics.md
/// section 6). Measured on Terzaghi's column (tests/verification/terzaghi_2d.opts, first step
/// dt = 0.2 s, exact settlement 4.6e-5 m): F = 0.25 gives 4.58e-5, F = 1 5.8e-5, F = 4 9.3e-5,
/// F = 10 1.4e-4, F = 1e12 8.3e-4 (the drained settlement: no excess pressure at all). Below
/// a tenth of 1/4 the stabilisation is as good as off.
constexpr double kStabilizationFactorMin = 0.025, kStabilizationFactorMax = 1.0;

std::string joinNames(const std::vector<PhysicalName> &names, int dim)
{
  std::string s;
  for (const auto &n : names)
    if (n.dim == dim) s += (s.empty() ? "" : ", ") + n.name;
  return s.empty() ? "(none)" : s;
}

} // namespace

/// A list option names each item once, and no item is empty ("-regions soil,,rock").
PetscErrorCode checkListNames(MPI_Comm comm, const std::string &option,
                              const std::vector<std::string> &items)
{
  std::set<std::string> seen;
  PetscFunctionBeginUser;
  for (const auto &item : items) {
    PetscCheck(!item.empty(), comm, PETSC_ERR_USER_INPUT,
               "option %s has an empty name in its list: expected comma-separated names",
               option.c_str());
    PetscCheck(seen.insert(item).second, comm, PETSC_ERR_USER_INPUT,
               "option %s names '%s' twice: each name must appear once", option.c_str(),
               item.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode findPhysical(MPI_Comm comm, const std::vector<PhysicalName> &names, int dim,
                            const std::string &name, const char *option, const char *what, int *tag)
{
  PetscFunctionBeginUser;
  for (const auto &n : names)
    if (n.dim == dim && n.name == name) {
      *tag = n.tag;
      PetscFunctionReturn(0);
    }
  SETERRQ(comm, PETSC_ERR_USER_INPUT,
          "%s: %s '%s' is not a physical group of dimension %d in the mesh; the mesh has: %s",
          option, what, name.c_str(), dim, joinNames(names, dim).c_str());
}

namespace {

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

/// A boundary's conditions, in its own -help section (PetscOptionsBegin in readSceneOptions).
PetscErrorCode readBoundary(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const Scene &scene,
                            const Boundary &b, std::vector<BoundaryCondition> &out)
{
  const std::string p = "-bc_" + b.name + "_";
  const char *comps[3] = {"ux", "uy", "uz"};
  PetscFunctionBeginUser;
  auto add = [&](BoundaryCondition bc) -> PetscErrorCode {
    PetscFunctionBeginUser;
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
    BoundaryCondition bc;
    bc.kind = BcKind::displacement;
    bc.component = c;
    bc.value = {v};
    bc.option = p + comps[c];
    PetscCall(add(bc));
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition("p", "prescribed pore pressure [Pa] (absolute: hydrostatic included)",
                        scene.hasPressure(), &v, &set));
    if (set) {
      PetscCheck(scene.hasPressure(), comm, PETSC_ERR_USER_INPUT,
                 "%sp: the scene has no pressure unknowns (drained, or no biot region)", p.c_str());
      BoundaryCondition bc;
      bc.kind = BcKind::pressure;
      bc.value = {v};
      bc.option = p + "p";
      PetscCall(add(bc));
    }
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition("p3",
                        "prescribed interface pressure p3 [Pa] where an interface with flow "
                        "meets the boundary",
                        scene.hasInterfacePressure(), &v, &set));
    if (set) {
      PetscCheck(scene.hasInterfacePressure(), comm, PETSC_ERR_USER_INPUT,
                 "%sp3: no interface of the scene has flow (-interface_<i>_flow)", p.c_str());
      BoundaryCondition bc;
      bc.kind = BcKind::interface_pressure;
      bc.value = {v};
      bc.option = p + "p3";
      PetscCall(add(bc));
    }
  }
  {
    std::vector<double> v;
    bool set = false;
    PetscCall(getRealList(PetscOptionsObject, p + "traction",
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
      BoundaryCondition bc;
      bc.kind = BcKind::traction;
      bc.value = v;
      bc.option = p + "traction";
      PetscCall(add(bc));
    }
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition("pressure",
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
      BoundaryCondition bc;
      bc.kind = BcKind::normal_pressure;
      bc.value = {v};
      bc.option = p + "pressure";
      PetscCall(add(bc));
    }
  }
  {
    double v = 0.0;
    bool set = false;
    PetscCall(condition("flux", "outward Darcy flux q.n [m/s] (positive: water leaves)",
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
      BoundaryCondition bc;
      bc.kind = BcKind::flux;
      bc.value = {v};
      bc.option = p + "flux";
      PetscCall(add(bc));
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

} // namespace

bool Scene::hasInterfacePressure() const
{
  return std::any_of(interfaces.begin(), interfaces.end(),
                     [](const Interface &i) { return i.flow; });
}

bool Scene::hasPressure() const
{
  if (drained) return false;
  return std::any_of(regions.begin(), regions.end(), [](const Region &r) { return r.porous(); });
}

int Scene::regionIndexOfTag(int tag) const
{
  for (size_t i = 0; i < regions.size(); ++i)
    if (regions[i].tag == tag) return (int)i;
  return -1;
}

PetscErrorCode readMeshOptions(MPI_Comm comm, Scene &scene)
{
  bool set = false;
  PetscFunctionBeginUser;
  // The scene-wide names first: "missing option -mesh" would hide that -mseh was given.
  PetscCall(checkOptionNames(comm, SceneNames{}));
  PetscOptionsBegin(comm, nullptr, "poroseam scene: mesh and output directory", kSceneDoc);
  PetscCall(getString(PetscOptionsObject, "-mesh",
                      "Gmsh mesh (.msh) or geometry (.geo, meshed by gmsh) (required)",
                      scene.mesh_file, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT,
             "missing option -mesh: name a Gmsh mesh (.msh) or geometry (.geo) file");
  PetscCall(getReal(PetscOptionsObject, "-mesh_size_factor",
                    "gmsh -clscale for a .geo [-] (0.5 halves every element size)",
                    &scene.mesh_size_factor, nullptr));
  PetscCheck(scene.mesh_size_factor > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-mesh_size_factor %g: must be > 0", scene.mesh_size_factor);
  {
    double order = scene.mesh_geometry_order;
    PetscCall(getReal(PetscOptionsObject, "-mesh_geometry_order",
                      "order of the cells' geometry: 1 (straight-sided) or 2 (second-order gmsh "
                      "cells, curved along curved boundaries; needs -displacement_order 2)",
                      &order, nullptr));
    char given[32];
    std::snprintf(given, sizeof given, "%g", order);
    PetscCheck(order == 1.0 || order == 2.0, comm, PETSC_ERR_USER_INPUT,
               "-mesh_geometry_order %s: expected 1 (straight-sided cells) or 2 (curved, "
               "second-order gmsh cells)",
               given);
    scene.mesh_geometry_order = (int)order;
  }
  PetscCall(getString(PetscOptionsObject, "-output_dir", "directory of the results",
                      scene.output_dir, nullptr));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

namespace {

/// The scene-wide physics and the initial state.
PetscErrorCode readPhysics(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                           const std::vector<PhysicalName> &names, int dim, Scene &scene)
{
  bool set = false;
  PetscFunctionBeginUser;
  scene.drained = false;
  PetscCall(getFlag(PetscOptionsObject, "-drained",
                    "drained analysis: no pressure unknowns anywhere", &scene.drained, nullptr));
  scene.axisymmetric = false;
  PetscCall(getFlag(PetscOptionsObject, "-axisymmetric",
                    "2D meshes: axisymmetric about the y axis, x = r >= 0 (results per full "
                    "circle)",
                    &scene.axisymmetric, nullptr));
  PetscCheck(!scene.axisymmetric || dim == 2, comm, PETSC_ERR_USER_INPUT,
             "-axisymmetric: needs a 2D mesh in the (r, z) = (x, y) plane; this mesh is %dD", dim);
  PetscCall(getReal(PetscOptionsObject, "-gravity",
                    "gravitational acceleration g [m/s2] along -y (2D) or -z (3D); 0: off",
                    &scene.gravity, nullptr));
  PetscCheck(scene.gravity >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "-gravity %g: give the magnitude g >= 0 (it acts along -y in 2D, -z in 3D)",
             scene.gravity);
  PetscCall(getReal(PetscOptionsObject, "-fluid_density", "water density rho_w [kg/m3]",
                    &scene.fluid_density, nullptr));
  PetscCall(getReal(PetscOptionsObject, "-fluid_viscosity", "water viscosity mu_w [Pa s]",
                    &scene.fluid_viscosity, nullptr));
  PetscCheck(scene.fluid_density > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-fluid_density %g: must be > 0", scene.fluid_density);
  PetscCheck(scene.fluid_viscosity > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-fluid_viscosity %g: must be > 0", scene.fluid_viscosity);
  PetscCall(getReal(PetscOptionsObject, "-stabilization_factor",
                    "pressure stabilisation factor F [-] (0 disables)", &scene.stabilization_factor,
                    nullptr));
  PetscCheck(scene.stabilization_factor >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "-stabilization_factor %g: must be >= 0", scene.stabilization_factor);
  {
    double order = scene.displacement_order;
    PetscCall(getReal(PetscOptionsObject, "-displacement_order",
                      "order of the displacement elements: 1 (equal order, stabilised) or 2 "
                      "(Taylor-Hood P2/P1, Q2/Q1; no stabilisation)",
                      &order, nullptr));
    char given[32];
    std::snprintf(given, sizeof given, "%g", order); // PETSc's %g would print "3."
    PetscCheck(order == 1.0 || order == 2.0, comm, PETSC_ERR_USER_INPUT,
               "-displacement_order %s: expected 1 (linear) or 2 (quadratic, Taylor-Hood)", given);
    scene.displacement_order = (int)order;
  }
  // Isoparametric: the curved cell is mapped by the displacement's own quadratic basis.
  PetscCheck(scene.mesh_geometry_order == 1 || scene.displacement_order == 2, comm,
             PETSC_ERR_USER_INPUT,
             "-mesh_geometry_order 2: curved cells need -displacement_order 2 (the quadratic "
             "displacement basis maps them; linear elements cannot follow the curve)");

  std::string initial = "none";
  PetscCall(getString(PetscOptionsObject, "-initial_state",
                      "none, or geostatic (K0 effective stresses and hydrostatic pressure)",
                      initial, nullptr));
  PetscCheck(initial == "none" || initial == "geostatic", comm, PETSC_ERR_USER_INPUT,
             "-initial_state %s: expected 'none' or 'geostatic'", initial.c_str());
  scene.geostatic = initial == "geostatic";
  PetscCheck(!scene.geostatic || scene.gravity > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-initial_state geostatic needs -gravity > 0");
  PetscCall(getReal(PetscOptionsObject, "-surface_elevation",
                    "soil surface elevation [m] of the geostatic state", &scene.surface_elevation,
                    nullptr));
  scene.water_level = scene.surface_elevation;
  PetscCall(getReal(PetscOptionsObject, "-water_level",
                    "phreatic level [m] of the hydrostatic pressure (default: the surface)",
                    &scene.water_level, nullptr));
  // The free water above the ground pushes on the boundaries it stands on; the geostatic
  // state balances that load, so with water above the surface it must be applied.
  std::vector<std::string> names_w;
  PetscCall(getStringList(PetscOptionsObject, "-water_load_boundaries",
                          "boundaries the free water stands on (comma-separated): they carry "
                          "its pressure",
                          names_w, &set));
  PetscCheck(!set || scene.gravity > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-water_load_boundaries: the water's pressure needs -gravity > 0");
  scene.water_load_boundaries.clear();
  for (const auto &name : names_w) {
    Boundary b;
    b.name = name;
    PetscCall(
        findPhysical(comm, names, dim - 1, name, "-water_load_boundaries", "boundary", &b.tag));
    for (const auto &other : scene.water_load_boundaries)
      PetscCheck(other.name != name, comm, PETSC_ERR_USER_INPUT,
                 "-water_load_boundaries: '%s' is listed twice; list each boundary once",
                 name.c_str());
    scene.water_load_boundaries.push_back(b);
  }
  PetscCheck(!scene.geostatic || scene.water_level <= scene.surface_elevation ||
                 !scene.water_load_boundaries.empty(),
             comm, PETSC_ERR_USER_INPUT,
             "-water_level %g is above -surface_elevation %g: the water's weight acts on the "
             "soil surface; name the boundaries it stands on with -water_load_boundaries",
             scene.water_level, scene.surface_elevation);
  PetscFunctionReturn(0);
}

/// The pressure stabilisation beta = F alpha^2 h^2 / (lambda + 2G) (docs/physics.md section 6)
/// has a meaningful range around F = 1/4: outside it the run goes on, with one warning line
/// that says what the factor does to the pressure.
PetscErrorCode warnStabilization(MPI_Comm comm, const Scene &scene)
{
  const double F = scene.stabilization_factor;
  PetscFunctionBeginUser;
  if (!scene.hasPressure()) PetscFunctionReturn(0); // no pressure to stabilise
  if (F < kStabilizationFactorMin)
    PetscCall(PetscPrintf(comm,
                          "poroseam: warning: -stabilization_factor %s %s the pressure "
                          "stabilisation: with equal-order elements for u and p the pressure of a "
                          "nearly undrained step (just after a load, low permeability, small "
                          "steps) is not reliable (inf-sup): it may oscillate from vertex to "
                          "vertex (meaningful range %s to %s, default 0.25)\n",
                          number(F).c_str(), F == 0.0 ? "turns off" : "all but turns off",
                          number(kStabilizationFactorMin).c_str(),
                          number(kStabilizationFactorMax).c_str()));
  else if (F > kStabilizationFactorMax)
    PetscCall(PetscPrintf(comm,
                          "poroseam: warning: -stabilization_factor %s is above its meaningful "
                          "range (%s to %s, default 0.25): the term F alpha^2 h^2/(lambda + 2G) "
                          "grad(dp/dt) spreads each pressure change over about sqrt(F) = %s cell "
                          "sizes, so the pressure is over-smoothed and the excess pressure drains "
                          "too fast (a large F: a drained response at once)\n",
                          number(F).c_str(), number(kStabilizationFactorMin).c_str(),
                          number(kStabilizationFactorMax).c_str(), number(std::sqrt(F)).c_str()));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readSceneOptions(MPI_Comm comm, const std::vector<PhysicalName> &names, int dim,
                                Scene &scene)
{
  bool set = false;
  PetscFunctionBeginUser;
  scene.dim = dim;
  // The lists first: with the names of the scene's parts known, a misspelt option is named
  // before it shows as a missing one ("missing option -region_soil_E" when -region_soil_e
  // was given) or as a wrong default.
  std::vector<std::string> regions, interfaces, boundaries;
  PetscOptionsBegin(comm, nullptr, "poroseam scene: its parts (physical groups of the mesh)",
                    kSceneDoc);
  PetscCall(getStringList(PetscOptionsObject, "-regions",
                          "the regions (cell groups), comma-separated; every cell in one", regions,
                          &set));
  PetscCheck(set && !regions.empty(), comm, PETSC_ERR_USER_INPUT,
             "missing option -regions: list the mesh regions (cell physical names: %s)",
             joinNames(names, dim).c_str());
  PetscCall(getStringList(PetscOptionsObject, "-boundaries",
                          "the boundaries (face groups; physical points, 3D curves: supports) the "
                          "scene uses, comma-separated",
                          boundaries, &set));
  PetscCall(getStringList(PetscOptionsObject, "-interfaces",
                          "the zero-thickness interfaces, comma-separated", interfaces, &set));
  PetscOptionsEnd();
  PetscCall(checkListNames(comm, "-regions", regions));
  scene.regions.clear();
  for (const auto &name : regions) {
    Region r;
    r.name = name;
    PetscCall(findPhysical(comm, names, dim, name, "-regions", "region", &r.tag));
    scene.regions.push_back(r);
  }
  PetscCall(checkListNames(comm, "-interfaces", interfaces));
  PetscCall(checkListNames(comm, "-boundaries", boundaries));
  scene.boundaries.clear();
  for (const auto &name : boundaries) {
    Boundary b;
    b.name = name;
    PetscCall(findBoundaryGroup(comm, names, dim, name, &b));
    scene.boundaries.push_back(b);
  }
  PetscCall(checkOptionNames(comm, SceneNames{dim, regions, boundaries, interfaces, names}));

  PetscOptionsBegin(comm, nullptr, "poroseam scene: physics and initial state", kSceneDoc);
  PetscCall(readPhysics(PetscOptionsObject, comm, names, dim, scene));
  PetscOptionsEnd();

  // Regions: every one is a cell group of the mesh (above) and has a material.
  for (auto &r : scene.regions) {
    const std::string title = "poroseam region " + r.name + " (-region_" + r.name + "_*)";
    PetscOptionsBegin(comm, nullptr, title.c_str(), kSceneDoc);
    PetscCall(readRegion(PetscOptionsObject, comm, r, scene.drained, scene.geostatic));
    PetscOptionsEnd();
  }

  scene.interfaces.clear();
  for (const auto &name : interfaces) {
    Interface i;
    i.name = name;
    const std::string title = "poroseam interface " + name + " (-interface_" + name + "_*)";
    PetscOptionsBegin(comm, nullptr, title.c_str(), kSceneDoc);
    PetscCall(readInterface(PetscOptionsObject, comm, names, dim, scene, i));
    PetscOptionsEnd();
    // A face group is split once: it cannot belong to two interfaces.
    for (const auto &other : scene.interfaces)
      for (const auto &surface : i.surfaces)
        PetscCheck(std::find(other.surfaces.begin(), other.surfaces.end(), surface) ==
                       other.surfaces.end(),
                   comm, PETSC_ERR_USER_INPUT,
                   "interfaces '%s' and '%s' both use the face group '%s' "
                   "(-interface_<i>_surfaces): a face group belongs to one interface",
                   other.name.c_str(), i.name.c_str(), surface.c_str());
    scene.interfaces.push_back(i);
  }
  scene.conditions.clear();
  for (const auto &b : scene.boundaries) {
    const std::string title = "poroseam boundary " + b.name + " (-bc_" + b.name + "_*)";
    PetscOptionsBegin(comm, nullptr, title.c_str(), kSceneDoc);
    PetscCall(readBoundary(PetscOptionsObject, comm, scene, b, scene.conditions));
    PetscOptionsEnd();
  }
  // An interface that can neither exchange water with its sides nor at its ends has an
  // undetermined pressure level (only its gradient enters): the linear systems are singular.
  const bool p3_prescribed =
      std::any_of(scene.conditions.begin(), scene.conditions.end(),
                  [](const BoundaryCondition &c) { return c.kind == BcKind::interface_pressure; });
  for (const auto &i : scene.interfaces)
    PetscCheck(!i.flow || i.transmissivity1 > 0.0 || i.transmissivity2 > 0.0 || p3_prescribed, comm,
               PETSC_ERR_USER_INPUT,
               "interface '%s' is sealed (-interface_%s_T1 0 and _T2 0) and no -bc_<b>_p3 is "
               "given: its water pressure is undetermined. For a perfect barrier (no water "
               "along it or across it) give -interface_%s_flow 0 (no interface pressure at "
               "all); to keep the flow along it, give T1 or T2 > 0, or, if it ends on a "
               "boundary b of the mesh, prescribe its pressure there with -bc_<b>_p3 (an "
               "interface that ends inside the mesh has no such end)",
               i.name.c_str(), i.name.c_str(), i.name.c_str());

  PetscCall(warnStabilization(comm, scene));
  PetscCall(readOutputOptions(comm, scene));
  PetscFunctionReturn(0);
}

void printSceneHelp(MPI_Comm comm)
{
  // Generated at configure time from docs/scenes.md, so -help and the docs never differ.
  static const char *text =
#include "scene_help.inc"
      ;
  PetscPrintf(comm, "%s\n", text);
}

} // namespace poroseam
