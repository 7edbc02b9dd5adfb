#include "poroseam/scene.hpp"

#include "poroseam/option_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <petscsys.h>
#include <set>
#include <sstream>

namespace poroseam {
namespace {

constexpr size_t kMaxList = 64;

PetscErrorCode getStringList(const std::string &option, std::vector<std::string> &out, bool *set)
{
  char *items[kMaxList];
  PetscInt n = kMaxList;
  PetscBool found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetStringArray(nullptr, nullptr, option.c_str(), items, &n, &found));
  out.clear();
  for (PetscInt i = 0; i < n; ++i) {
    out.emplace_back(items[i]);
    PetscCall(PetscFree(items[i]));
  }
  *set = found;
  PetscFunctionReturn(0);
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

/// Parses a number, accepting what PETSc accepts for reals (1e7, 2.5, -3); returns false
/// for anything else so that the error can name the option.
bool parseNumber(const std::string &text, double *value)
{
  const char *begin = text.c_str();
  char *end = nullptr;
  const double v = std::strtod(begin, &end);
  while (end && (*end == ' ' || *end == '\t'))
    ++end;
  if (end == begin || !end || *end != '\0' || !std::isfinite(v)) return false;
  *value = v;
  return true;
}

PetscErrorCode getReal(const std::string &option, double *value, bool *set)
{
  char buffer[256];
  PetscBool found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(
      PetscOptionsGetString(nullptr, nullptr, option.c_str(), buffer, sizeof(buffer), &found));
  if (found) {
    double v;
    PetscCheck(parseNumber(buffer, &v), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
               "option %s %s: expected a number", option.c_str(),
               buffer[0] ? buffer : "(no value)");
    *value = v;
  }
  if (set) *set = found;
  PetscFunctionReturn(0);
}

PetscErrorCode getRequiredReal(MPI_Comm comm, const std::string &option, const std::string &what,
                               double *value)
{
  bool set = false;
  PetscFunctionBeginUser;
  PetscCall(getReal(option, value, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT, "missing option %s: %s is required", option.c_str(),
             what.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode getString(const std::string &option, std::string &value, bool *set)
{
  char buffer[PETSC_MAX_PATH_LEN];
  PetscBool found = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(
      PetscOptionsGetString(nullptr, nullptr, option.c_str(), buffer, sizeof(buffer), &found));
  if (found) value = buffer;
  if (set) *set = found;
  PetscFunctionReturn(0);
}

PetscErrorCode getRealList(const std::string &option, std::vector<double> &values, bool *set)
{
  std::string text;
  bool found = false;
  PetscFunctionBeginUser;
  PetscCall(getString(option, text, &found));
  values.clear();
  if (found) {
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
      double v;
      PetscCheck(parseNumber(item, &v), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
                 "option %s %s: expected comma-separated numbers", option.c_str(), text.c_str());
      values.push_back(v);
    }
  }
  *set = found;
  PetscFunctionReturn(0);
}

std::string joinNames(const std::vector<PhysicalName> &names, int dim)
{
  std::string s;
  for (const auto &n : names)
    if (n.dim == dim) s += (s.empty() ? "" : ", ") + n.name;
  return s.empty() ? "(none)" : s;
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

PetscErrorCode readRegion(MPI_Comm comm, Region &r, bool gravity, bool drained)
{
  const std::string p = "-region_" + r.name + "_";
  std::string material;
  bool set = false;
  PetscFunctionBeginUser;
  PetscCall(getString(p + "material", material, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT,
             "missing option %smaterial: region '%s' needs "
             "'elastic', 'biot' or 'mohr_coulomb'",
             p.c_str(), r.name.c_str());
  if (material == "elastic")
    r.model = MaterialModel::elastic;
  else if (material == "biot")
    r.model = MaterialModel::biot;
  else if (material == "mohr_coulomb")
    r.model = MaterialModel::mohr_coulomb;
  else
    SETERRQ(comm, PETSC_ERR_USER_INPUT,
            "%smaterial %s: expected 'elastic', 'biot' or 'mohr_coulomb'", p.c_str(),
            material.c_str());

  PetscCall(getRequiredReal(comm, p + "E", "Young's modulus [Pa] of region " + r.name, &r.young));
  PetscCheck(r.young > 0.0, comm, PETSC_ERR_USER_INPUT, "%sE = %g: Young's modulus must be > 0",
             p.c_str(), r.young);
  PetscCall(getRequiredReal(comm, p + "nu", "Poisson's ratio of region " + r.name, &r.poisson));
  PetscCheck(r.poisson > -1.0 && r.poisson < 0.5, comm, PETSC_ERR_USER_INPUT,
             "%snu = %g: Poisson's ratio must lie in (-1, 0.5)", p.c_str(), r.poisson);
  PetscCall(getReal(p + "rho_s", &r.solid_density, nullptr));
  PetscCheck(r.solid_density >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "%srho_s = %g: density must be >= 0", p.c_str(), r.solid_density);
  r.k0 = r.poisson / (1.0 - r.poisson);
  PetscCall(getReal(p + "K0", &r.k0, nullptr));
  PetscCheck(r.k0 >= 0.0, comm, PETSC_ERR_USER_INPUT, "%sK0 = %g: must be >= 0", p.c_str(), r.k0);
  {
    // Read as text so that a bad value gets our one-line message, not PETSc's trace.
    std::string ground;
    PetscCall(getString(p + "ground", ground, &set));
    if (set) {
      std::string v = ground;
      for (auto &ch : v)
        ch = (char)std::tolower((unsigned char)ch);
      const bool yes = v.empty() || v == "true" || v == "1" || v == "yes" || v == "on";
      const bool no = v == "false" || v == "0" || v == "no" || v == "off";
      PetscCheck(yes || no, comm, PETSC_ERR_USER_INPUT,
                 "%sground %s: expected true or false (is region '%s' part of the ground column "
                 "of the geostatic state)",
                 p.c_str(), ground.c_str(), r.name.c_str());
      r.ground = yes;
    }
  }
  if (r.porous()) {
    PetscCall(getReal(p + "porosity", &r.porosity, nullptr));
    PetscCheck(r.porosity >= 0.0 && r.porosity < 1.0, comm, PETSC_ERR_USER_INPUT,
               "%sporosity = %g: must lie in [0, 1)", p.c_str(), r.porosity);
    if (!drained) {
      PetscCall(getRequiredReal(comm, p + "permeability",
                                "intrinsic permeability [m2] of biot region " + r.name,
                                &r.permeability));
    } else {
      PetscCall(getReal(p + "permeability", &r.permeability, nullptr));
    }
    PetscCheck(r.permeability >= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%spermeability = %g: must be >= 0", p.c_str(), r.permeability);
    PetscCall(getReal(p + "biot_alpha", &r.biot_coefficient, nullptr));
    PetscCheck(r.biot_coefficient > 0.0 && r.biot_coefficient <= 1.0, comm, PETSC_ERR_USER_INPUT,
               "%sbiot_alpha = %g: must lie in (0, 1]", p.c_str(), r.biot_coefficient);
    PetscCall(getReal(p + "storage", &r.storage, nullptr));
    PetscCheck(r.storage >= 0.0, comm, PETSC_ERR_USER_INPUT, "%sstorage = %g: 1/M must be >= 0",
               p.c_str(), r.storage);
  }
  if (r.model == MaterialModel::mohr_coulomb) {
    // Strength of the skeleton (effective stress): c, phi, psi (non-associated when psi < phi)
    // and the optional tension cut-off on the largest principal effective stress.
    PetscCall(
        getRequiredReal(comm, p + "cohesion", "cohesion c [Pa] of region " + r.name, &r.cohesion));
    PetscCall(getRequiredReal(comm, p + "friction_angle",
                              "friction angle phi [degrees] of region " + r.name,
                              &r.friction_angle));
    PetscCall(getRequiredReal(comm, p + "dilation_angle",
                              "dilation angle psi [degrees] of region " + r.name,
                              &r.dilation_angle));
    PetscCheck(r.cohesion >= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%scohesion = %g: the cohesion [Pa] must be >= 0", p.c_str(), r.cohesion);
    PetscCheck(r.friction_angle >= 0.0 && r.friction_angle < 90.0, comm, PETSC_ERR_USER_INPUT,
               "%sfriction_angle = %g: the friction angle [degrees] must lie in [0, 90)", p.c_str(),
               r.friction_angle);
    PetscCheck(r.cohesion > 0.0 || r.friction_angle > 0.0, comm, PETSC_ERR_USER_INPUT,
               "%scohesion = 0 and %sfriction_angle = 0: a soil without cohesion and friction "
               "has no strength; give c > 0 or phi > 0",
               p.c_str(), p.c_str());
    PetscCheck(r.dilation_angle >= 0.0 && r.dilation_angle <= r.friction_angle, comm,
               PETSC_ERR_USER_INPUT,
               "%sdilation_angle = %g: the dilation angle [degrees] must lie in [0, phi] = [0, "
               "%g] (%sfriction_angle)",
               p.c_str(), r.dilation_angle, r.friction_angle, p.c_str());
    bool cutoff = false;
    PetscCall(getReal(p + "tension_cutoff", &r.tension_cutoff, &cutoff));
    if (cutoff) {
      PetscCheck(r.tension_cutoff >= 0.0, comm, PETSC_ERR_USER_INPUT,
                 "%stension_cutoff = %g: the tensile strength [Pa] must be >= 0", p.c_str(),
                 r.tension_cutoff);
      // Beyond the apex c / tan(phi) the cut-off would never be reached.
      const double apex = r.friction_angle > 0.0
                              ? r.cohesion / std::tan(r.friction_angle * M_PI / 180.0)
                              : INFINITY;
      PetscCheck(r.tension_cutoff <= apex, comm, PETSC_ERR_USER_INPUT,
                 "%stension_cutoff = %g: must not exceed the apex of the Mohr-Coulomb cone c / "
                 "tan(phi) = %g Pa (omit the option for no cut-off)",
                 p.c_str(), r.tension_cutoff, apex);
    } else {
      r.tension_cutoff = -1.0;
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode readTimeFunction(MPI_Comm comm, const std::string &option, TimeFunction &f)
{
  double ramp = 0.0;
  bool ramp_set = false, table_set = false;
  std::string table;
  PetscFunctionBeginUser;
  PetscCall(getReal(option + "_ramp", &ramp, &ramp_set));
  PetscCall(getString(option + "_table", table, &table_set));
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
    f = TimeFunction::table(t, v);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode readBoundary(MPI_Comm comm, const Scene &scene, const Boundary &b,
                            std::vector<BoundaryCondition> &out)
{
  const std::string p = "-bc_" + b.name + "_";
  const char *comps[3] = {"ux", "uy", "uz"};
  PetscFunctionBeginUser;
  auto add = [&](BoundaryCondition bc) -> PetscErrorCode {
    PetscFunctionBeginUser;
    bc.boundary = b.name;
    bc.tag = b.tag;
    PetscCall(readTimeFunction(comm, bc.option, bc.time));
    out.push_back(bc);
    PetscFunctionReturn(0);
  };
  for (int c = 0; c < 3; ++c) {
    double v = 0.0;
    bool set = false;
    PetscCall(getReal(p + comps[c], &v, &set));
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
    PetscCall(getReal(p + "p", &v, &set));
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
    PetscCall(getReal(p + "p3", &v, &set));
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
    PetscCall(getRealList(p + "traction", v, &set));
    if (set) {
      PetscCheck((int)v.size() == scene.dim, comm, PETSC_ERR_USER_INPUT,
                 "%straction: expected %d comma-separated components, got %d", p.c_str(), scene.dim,
                 (int)v.size());
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
    PetscCall(getReal(p + "flux", &v, &set));
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
  PetscFunctionReturn(0);
}

PetscErrorCode readInterface(MPI_Comm comm, const std::vector<PhysicalName> &names, int dim,
                             const Scene &scene, Interface &i)
{
  const std::string p = "-interface_" + i.name + "_";
  bool set = false;
  PetscFunctionBeginUser;
  PetscCall(getStringList(p + "surfaces", i.surfaces, &set));
  if (!set) i.surfaces = {i.name};
  PetscCall(checkListNames(comm, p + "surfaces", i.surfaces));
  for (const auto &surface : i.surfaces) {
    int tag;
    PetscCall(findPhysical(comm, names, dim - 1, surface, (p + "surfaces").c_str(),
                           "interface surface", &tag));
    i.tags.push_back(tag);
  }
  PetscCall(getString(p + "side1", i.side1, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT,
             "missing option %sside1: name the region on side 1 of interface '%s'", p.c_str(),
             i.name.c_str());
  bool known = false;
  for (const auto &r : scene.regions)
    if (r.name == i.side1) known = true, i.side1_tag = r.tag;
  PetscCheck(known, comm, PETSC_ERR_USER_INPUT, "%sside1 %s: not a region listed in -regions",
             p.c_str(), i.side1.c_str());
  PetscCall(getRequiredReal(comm, p + "KN",
                            "normal penalty stiffness K_N [Pa/m] of interface " + i.name,
                            &i.normal_stiffness));
  PetscCheck(i.normal_stiffness > 0.0, comm, PETSC_ERR_USER_INPUT, "%sKN = %g: must be > 0",
             p.c_str(), i.normal_stiffness);
  PetscCall(getRequiredReal(comm, p + "KT",
                            "tangential penalty stiffness K_T [Pa/m] of interface " + i.name,
                            &i.tangential_stiffness));
  PetscCheck(i.tangential_stiffness > 0.0, comm, PETSC_ERR_USER_INPUT, "%sKT = %g: must be > 0",
             p.c_str(), i.tangential_stiffness);
  PetscCall(getRequiredReal(comm, p + "friction", "friction coefficient mu of interface " + i.name,
                            &i.friction));
  PetscCheck(i.friction >= 0.0, comm, PETSC_ERR_USER_INPUT, "%sfriction = %g: must be >= 0",
             p.c_str(), i.friction);
  // Shear dilation (docs/physics.md section 4): angle psi in degrees, optional slip limit.
  double psi = 0.0, slip_limit = 0.0;
  PetscCall(getReal(p + "dilation_angle", &psi, nullptr));
  PetscCheck(psi >= 0.0 && psi < 90.0, comm, PETSC_ERR_USER_INPUT,
             "%sdilation_angle = %g: expected a dilation angle in degrees, 0 <= psi < 90",
             p.c_str(), psi);
  i.dilation = std::tan(psi * M_PI / 180.0);
  PetscCall(getReal(p + "dilation_limit", &slip_limit, &set));
  if (set) {
    PetscCheck(slip_limit >= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%sdilation_limit = %g: expected the plastic slip [m] after which the joint stops "
               "dilating, >= 0",
               p.c_str(), slip_limit);
    i.dilation_slip_limit = slip_limit;
  }
  std::string rule = "gauss";
  PetscCall(getString(p + "integration", rule, nullptr));
  PetscCheck(rule == "gauss" || rule == "nodal", comm, PETSC_ERR_USER_INPUT,
             "%sintegration %s: expected 'gauss' or 'nodal'", p.c_str(), rule.c_str());
  i.nodal_integration = rule == "nodal";
  PetscBool flow = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, (p + "flow").c_str(), &flow, nullptr));
  i.flow = flow;
  if (i.flow) {
    PetscCheck(!scene.drained, comm, PETSC_ERR_USER_INPUT,
               "%sflow: a drained scene has no pressure, so no interface flow", p.c_str());
    PetscCall(getRequiredReal(comm, p + "D0", "hydraulic aperture D0 [m] of interface " + i.name,
                              &i.aperture0));
    PetscCheck(i.aperture0 > 0.0, comm, PETSC_ERR_USER_INPUT, "%sD0 = %g: must be > 0", p.c_str(),
               i.aperture0);
    PetscCall(getRequiredReal(comm, p + "T1",
                              "transmissivity T1 [m/(Pa s)] between side 1 and interface " + i.name,
                              &i.transmissivity1));
    PetscCall(getRequiredReal(
        comm, p + "T2", "transmissivity T2 [m/(Pa s)] between interface " + i.name + " and side 2",
        &i.transmissivity2));
    PetscCheck(i.transmissivity1 >= 0.0 && i.transmissivity2 >= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%sT1 = %g, %sT2 = %g: transmissivities must be >= 0 (0: impervious side)",
               p.c_str(), i.transmissivity1, p.c_str(), i.transmissivity2);
  }
  PetscFunctionReturn(0);
}

/// Names used in options of the form -<prefix><name>_..., for spotting typos.
std::set<std::string> optionsWithPrefix(const std::string &all, const std::string &prefix)
{
  std::set<std::string> found;
  std::istringstream in(all);
  std::string token;
  while (in >> token)
    if (token.rfind("-" + prefix, 0) == 0) found.insert(token.substr(1));
  return found;
}

PetscErrorCode readProbes(MPI_Comm comm, Scene &scene)
{
  char *all = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  const std::string text = all;
  PetscCall(PetscFree(all));
  for (const auto &opt : optionsWithPrefix(text, "probe_")) {
    Probe probe;
    probe.name = opt.substr(6);
    std::vector<double> x;
    bool set = false;
    PetscCall(getRealList("-" + opt, x, &set));
    PetscCheck((int)x.size() == scene.dim, comm, PETSC_ERR_USER_INPUT,
               "-%s: expected %d comma-separated coordinates, got %d", opt.c_str(), scene.dim,
               (int)x.size());
    for (int d = 0; d < scene.dim; ++d)
      probe.x[d] = x[d];
    scene.probes.push_back(probe);
  }
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
  PetscCall(getString("-mesh", scene.mesh_file, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT,
             "missing option -mesh: name a Gmsh mesh (.msh) or geometry (.geo) file");
  PetscCall(getReal("-mesh_size_factor", &scene.mesh_size_factor, nullptr));
  PetscCheck(scene.mesh_size_factor > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-mesh_size_factor %g: must be > 0", scene.mesh_size_factor);
  PetscCall(getString("-output_dir", scene.output_dir, nullptr));
  PetscFunctionReturn(0);
}

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
  PetscCall(getStringList("-regions", regions, &set));
  PetscCheck(set && !regions.empty(), comm, PETSC_ERR_USER_INPUT,
             "missing option -regions: list the mesh regions (cell physical names: %s)",
             joinNames(names, dim).c_str());
  PetscCall(checkListNames(comm, "-regions", regions));
  scene.regions.clear();
  for (const auto &name : regions) {
    Region r;
    r.name = name;
    PetscCall(findPhysical(comm, names, dim, name, "-regions", "region", &r.tag));
    scene.regions.push_back(r);
  }
  PetscCall(getStringList("-interfaces", interfaces, &set));
  PetscCall(checkListNames(comm, "-interfaces", interfaces));
  PetscCall(getStringList("-boundaries", boundaries, &set));
  PetscCall(checkListNames(comm, "-boundaries", boundaries));
  scene.boundaries.clear();
  for (const auto &name : boundaries) {
    Boundary b;
    b.name = name;
    PetscCall(findPhysical(comm, names, dim - 1, name, "-boundaries", "boundary", &b.tag));
    scene.boundaries.push_back(b);
  }
  PetscCall(checkOptionNames(comm, SceneNames{dim, regions, boundaries, interfaces, names}));

  PetscBool flag = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-drained", &flag, nullptr));
  scene.drained = flag;
  flag = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-axisymmetric", &flag, nullptr));
  scene.axisymmetric = flag;
  PetscCheck(!scene.axisymmetric || dim == 2, comm, PETSC_ERR_USER_INPUT,
             "-axisymmetric: needs a 2D mesh in the (r, z) = (x, y) plane; this mesh is %dD", dim);
  PetscCall(getReal("-gravity", &scene.gravity, nullptr));
  PetscCheck(scene.gravity >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "-gravity %g: give the magnitude g >= 0 (it acts along -y in 2D, -z in 3D)",
             scene.gravity);
  PetscCall(getReal("-fluid_density", &scene.fluid_density, nullptr));
  PetscCall(getReal("-fluid_viscosity", &scene.fluid_viscosity, nullptr));
  PetscCheck(scene.fluid_density > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-fluid_density %g: must be > 0", scene.fluid_density);
  PetscCheck(scene.fluid_viscosity > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-fluid_viscosity %g: must be > 0", scene.fluid_viscosity);
  PetscCall(getReal("-stabilization_factor", &scene.stabilization_factor, nullptr));
  PetscCheck(scene.stabilization_factor >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "-stabilization_factor %g: must be >= 0", scene.stabilization_factor);

  std::string initial = "none";
  PetscCall(getString("-initial_state", initial, nullptr));
  PetscCheck(initial == "none" || initial == "geostatic", comm, PETSC_ERR_USER_INPUT,
             "-initial_state %s: expected 'none' or 'geostatic'", initial.c_str());
  scene.geostatic = initial == "geostatic";
  PetscCheck(!scene.geostatic || scene.gravity > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-initial_state geostatic needs -gravity > 0");
  PetscCall(getReal("-surface_elevation", &scene.surface_elevation, nullptr));
  scene.water_level = scene.surface_elevation;
  PetscCall(getReal("-water_level", &scene.water_level, nullptr));
  {
    // The free water above the ground pushes on the boundaries it stands on; the geostatic
    // state balances that load, so with water above the surface it must be applied.
    std::vector<std::string> names_w;
    PetscCall(getStringList("-water_load_boundaries", names_w, &set));
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
  }

  // Regions: every one is a cell group of the mesh (above) and has a material.
  for (auto &r : scene.regions)
    PetscCall(readRegion(comm, r, scene.gravity > 0.0, scene.drained));

  scene.interfaces.clear();
  for (const auto &name : interfaces) {
    Interface i;
    i.name = name;
    PetscCall(readInterface(comm, names, dim, scene, i));
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
  for (const auto &b : scene.boundaries)
    PetscCall(readBoundary(comm, scene, b, scene.conditions));
  // An interface that can neither exchange water with its sides nor at its ends has an
  // undetermined pressure level (only its gradient enters): the linear systems are singular.
  const bool p3_prescribed =
      std::any_of(scene.conditions.begin(), scene.conditions.end(),
                  [](const BoundaryCondition &c) { return c.kind == BcKind::interface_pressure; });
  for (const auto &i : scene.interfaces)
    PetscCheck(!i.flow || i.transmissivity1 > 0.0 || i.transmissivity2 > 0.0 || p3_prescribed, comm,
               PETSC_ERR_USER_INPUT,
               "interface '%s' is sealed (-interface_%s_T1 0 and _T2 0) and no -bc_<b>_p3 is "
               "given: its water pressure is undetermined. Give T1 or T2 > 0, or prescribe p3 "
               "where it meets a boundary, or drop -interface_%s_flow",
               i.name.c_str(), i.name.c_str(), i.name.c_str());

  double every = scene.output_every;
  PetscCall(getReal("-output_fields_every", &every, nullptr));
  PetscCheck(every >= 0 && every == std::floor(every), comm, PETSC_ERR_USER_INPUT,
             "-output_fields_every %g: expected a whole number >= 0", every);
  scene.output_every = (int)every;
  scene.probes.clear();
  PetscCall(readProbes(comm, scene));
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
