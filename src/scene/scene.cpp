// The scene from its options: the mesh options, the scene-wide physics, the lists of
// regions, interfaces and boundaries with their physical groups, and -help's scene page.
// Each region's, interface's and boundary's own options are read in scene_region.cpp,
// scene_interface.cpp and scene_boundary.cpp (scene_parts.hpp).
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

/// The meaningful range of -stabilization_factor F around the optimal 1/4 (docs/physics.md
/// section 6). Measured on Terzaghi's column (tests/verification/terzaghi_2d.opts, first step
/// dt = 0.2 s, exact settlement 4.6e-5 m): F = 0.25 gives 4.58e-5, F = 1 5.8e-5, F = 4 9.3e-5,
/// F = 10 1.4e-4, F = 1e12 8.3e-4 (the drained settlement: no excess pressure at all). Below
/// a tenth of 1/4 the stabilisation is as good as off.
constexpr double kStabilizationFactorMin = 0.025, kStabilizationFactorMax = 1.0;

} // namespace

/// A number as %g writes it (PETSc's own %g in messages adds a trailing dot: "5.").
std::string number(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

std::string joinNames(const std::vector<PhysicalName> &names, int dim)
{
  std::string s;
  for (const auto &n : names)
    if (n.dim == dim) s += (s.empty() ? "" : ", ") + n.name;
  return s.empty() ? "(none)" : s;
}

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

namespace {

/// An element order, 1 or 2 (-mesh_geometry_order, -displacement_order): read as a number so
/// that "1.5" or "3" is named in the error as given.
PetscErrorCode readOrder(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                         const OptionSpec &option, const char *expected, int *order)
{
  double value = *order;
  PetscFunctionBeginUser;
  PetscCall(getReal(PetscOptionsObject, option, &value, nullptr));
  char given[32];
  std::snprintf(given, sizeof given, "%g", value); // PETSc's %g would print "3."
  PetscCheck(value == 1.0 || value == 2.0, comm, PETSC_ERR_USER_INPUT, "%s %s: expected %s",
             option.flag, given, expected);
  *order = (int)value;
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode readMeshOptions(MPI_Comm comm, Scene &scene)
{
  bool set = false;
  PetscFunctionBeginUser;
  // The scene-wide names first: "missing option -mesh" would hide that -mseh was given.
  PetscCall(checkOptionNames(comm, SceneNames{}));
  PetscOptionsBegin(comm, nullptr, "poroseam scene: mesh, element order and output directory",
                    kSceneDoc);
  PetscCall(getString(PetscOptionsObject, spec(Option::mesh), scene.mesh_file, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT,
             "missing option -mesh: name a Gmsh mesh (.msh) or geometry (.geo) file");
  PetscCall(getReal(PetscOptionsObject, spec(Option::mesh_size_factor), &scene.mesh_size_factor,
                    nullptr));
  PetscCheck(scene.mesh_size_factor > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-mesh_size_factor %g: must be > 0", scene.mesh_size_factor);
  PetscCall(readOrder(PetscOptionsObject, comm, spec(Option::mesh_geometry_order),
                      "1 (straight-sided cells) or 2 (curved, second-order gmsh cells)",
                      &scene.mesh_geometry_order));
  // Read with the mesh: the memory estimate made before the mesh is read depends on it (the
  // solver preset auto chooses by order, solver_preset.hpp).
  PetscCall(readOrder(PetscOptionsObject, comm, spec(Option::displacement_order),
                      "1 (linear) or 2 (quadratic, Taylor-Hood)", &scene.displacement_order));
  PetscCall(getString(PetscOptionsObject, spec(Option::output_dir), scene.output_dir, nullptr));
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
  PetscCall(getFlag(PetscOptionsObject, spec(Option::drained), &scene.drained, nullptr));
  scene.axisymmetric = false;
  PetscCall(getFlag(PetscOptionsObject, spec(Option::axisymmetric), &scene.axisymmetric, nullptr));
  PetscCheck(!scene.axisymmetric || dim == 2, comm, PETSC_ERR_USER_INPUT,
             "-axisymmetric: needs a 2D mesh in the (r, z) = (x, y) plane; this mesh is %dD", dim);
  PetscCall(getReal(PetscOptionsObject, spec(Option::gravity), &scene.gravity, nullptr));
  PetscCheck(scene.gravity >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "-gravity %g: give the magnitude g >= 0 (it acts along -y in 2D, -z in 3D)",
             scene.gravity);
  PetscCall(
      getReal(PetscOptionsObject, spec(Option::fluid_density), &scene.fluid_density, nullptr));
  PetscCall(
      getReal(PetscOptionsObject, spec(Option::fluid_viscosity), &scene.fluid_viscosity, nullptr));
  PetscCheck(scene.fluid_density > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-fluid_density %g: must be > 0", scene.fluid_density);
  PetscCheck(scene.fluid_viscosity > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-fluid_viscosity %g: must be > 0", scene.fluid_viscosity);
  PetscCall(getReal(PetscOptionsObject, spec(Option::stabilization_factor),
                    &scene.stabilization_factor, nullptr));
  PetscCheck(scene.stabilization_factor >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "-stabilization_factor %g: must be >= 0", scene.stabilization_factor);
  // Isoparametric: the curved cell is mapped by the displacement's own quadratic basis.
  PetscCheck(scene.mesh_geometry_order == 1 || scene.displacement_order == 2, comm,
             PETSC_ERR_USER_INPUT,
             "-mesh_geometry_order 2: curved cells need -displacement_order 2 (the quadratic "
             "displacement basis maps them; linear elements cannot follow the curve)");

  std::string initial = "none";
  PetscCall(getString(PetscOptionsObject, spec(Option::initial_state), initial, nullptr));
  PetscCheck(initial == "none" || initial == "geostatic", comm, PETSC_ERR_USER_INPUT,
             "-initial_state %s: expected 'none' or 'geostatic'", initial.c_str());
  scene.geostatic = initial == "geostatic";
  PetscCheck(!scene.geostatic || scene.gravity > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-initial_state geostatic needs -gravity > 0");
  PetscCall(getReal(PetscOptionsObject, spec(Option::surface_elevation), &scene.surface_elevation,
                    nullptr));
  scene.water_level = scene.surface_elevation;
  PetscCall(getReal(PetscOptionsObject, spec(Option::water_level), &scene.water_level, nullptr));
  // The free water above the ground pushes on the boundaries it stands on; the geostatic
  // state balances that load, so with water above the surface it must be applied.
  std::vector<std::string> names_w;
  PetscCall(getStringList(PetscOptionsObject, spec(Option::water_load_boundaries), names_w, &set));
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
  PetscCall(getStringList(PetscOptionsObject, spec(Option::regions), regions, &set));
  PetscCheck(set && !regions.empty(), comm, PETSC_ERR_USER_INPUT,
             "missing option -regions: list the mesh regions (cell physical names: %s)",
             joinNames(names, dim).c_str());
  PetscCall(getStringList(PetscOptionsObject, spec(Option::boundaries), boundaries, &set));
  PetscCall(getStringList(PetscOptionsObject, spec(Option::interfaces), interfaces, &set));
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
