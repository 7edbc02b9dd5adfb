// An interface's options: its face groups, side 1, penalty stiffnesses, friction, dilation,
// integration rule and flow, each checked with a message naming the option. Part of
// readSceneOptions (scene.cpp), in the interface's -help section.
#include "scene_parts.hpp"

#include "poroseam/scene_options.hpp"

#include <cmath>

namespace poroseam {

/// An interface's options, in its own -help section (PetscOptionsBegin in readSceneOptions).
PetscErrorCode readInterface(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                             const std::vector<PhysicalName> &names, int dim, const Scene &scene,
                             Interface &i)
{
  const std::string p = "-interface_" + i.name + "_";
  bool set = false;
  PetscFunctionBeginUser;
  PetscCall(getStringList(PetscOptionsObject, p + key(InterfaceKey::surfaces),
                          "its Gmsh face groups, comma-separated (default: the group named " +
                              i.name + ")",
                          i.surfaces, &set));
  if (!set) i.surfaces = {i.name};
  PetscCall(checkListNames(comm, p + key(InterfaceKey::surfaces), i.surfaces));
  i.tags.clear();
  for (const auto &surface : i.surfaces) {
    int tag;
    // Without the option, its default (the group named like the interface) is what is
    // missing: the message names the option to set.
    const std::string option = set ? p + key(InterfaceKey::surfaces)
                                   : "interface '" + i.name + "' (without " + p +
                                         "surfaces, the face group named '" + i.name + "'; set " +
                                         p + "surfaces to its groups)";
    PetscCall(
        findPhysical(comm, names, dim - 1, surface, option.c_str(), "interface surface", &tag));
    i.tags.push_back(tag);
  }
  PetscCall(getString(PetscOptionsObject, p + key(InterfaceKey::side1),
                      "the region on side 1: the normal e1 points from it to side 2 (required)",
                      i.side1, &set));
  PetscCheck(set, comm, PETSC_ERR_USER_INPUT,
             "missing option %sside1: name the region on side 1 of interface '%s'", p.c_str(),
             i.name.c_str());
  bool known = false;
  for (const auto &r : scene.regions)
    if (r.name == i.side1) known = true, i.side1_tag = r.tag;
  PetscCheck(known, comm, PETSC_ERR_USER_INPUT, "%sside1 %s: not a region listed in -regions",
             p.c_str(), i.side1.c_str());
  PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(InterfaceKey::KN),
                            "normal penalty stiffness K_N [Pa/m] of interface " + i.name,
                            &i.normal_stiffness));
  PetscCheck(i.normal_stiffness > 0.0, comm, PETSC_ERR_USER_INPUT, "%sKN = %g: must be > 0",
             p.c_str(), i.normal_stiffness);
  PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(InterfaceKey::KT),
                            "tangential penalty stiffness K_T [Pa/m] of interface " + i.name,
                            &i.tangential_stiffness));
  PetscCheck(i.tangential_stiffness > 0.0, comm, PETSC_ERR_USER_INPUT, "%sKT = %g: must be > 0",
             p.c_str(), i.tangential_stiffness);
  PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(InterfaceKey::friction),
                            "Coulomb friction coefficient mu [-] of interface " + i.name,
                            &i.friction));
  PetscCheck(i.friction >= 0.0, comm, PETSC_ERR_USER_INPUT, "%sfriction = %g: must be >= 0",
             p.c_str(), i.friction);
  // Shear dilation (docs/physics.md section 4): angle psi in degrees, optional slip limit.
  double psi = 0.0, slip_limit = 0.0;
  PetscCall(getReal(PetscOptionsObject, p + key(InterfaceKey::dilation_angle),
                    "shear dilation angle psi [deg] of interface " + i.name + ", in [0, 90)", &psi,
                    nullptr));
  PetscCheck(psi >= 0.0 && psi < 90.0, comm, PETSC_ERR_USER_INPUT,
             "%sdilation_angle = %g: expected a dilation angle in degrees, 0 <= psi < 90",
             p.c_str(), psi);
  i.dilation = std::tan(psi * M_PI / 180.0);
  PetscCall(getReal(PetscOptionsObject, p + key(InterfaceKey::dilation_limit),
                    "plastic slip [m] of interface " + i.name +
                        " after which it stops dilating (optional; none: no limit)",
                    &slip_limit, &set, "none"));
  if (set) {
    PetscCheck(slip_limit >= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%sdilation_limit = %g: expected the plastic slip [m] after which the joint stops "
               "dilating, >= 0",
               p.c_str(), slip_limit);
    i.dilation_slip_limit = slip_limit;
  }
  std::string rule = "gauss";
  PetscCall(getString(PetscOptionsObject, p + key(InterfaceKey::integration),
                      "integration points: gauss, or nodal (Newton-Cotes/Lobatto at the nodes)",
                      rule, nullptr));
  PetscCheck(rule == "gauss" || rule == "nodal", comm, PETSC_ERR_USER_INPUT,
             "%sintegration %s: expected 'gauss' or 'nodal'", p.c_str(), rule.c_str());
  i.nodal_integration = rule == "nodal";
  i.flow = false;
  PetscCall(getFlag(PetscOptionsObject, p + key(InterfaceKey::flow),
                    "water flows in and through the interface (interface pressure p3)", &i.flow,
                    nullptr));
  if (i.flow) {
    PetscCheck(!scene.drained, comm, PETSC_ERR_USER_INPUT,
               "%sflow: a drained scene has no pressure, so no interface flow", p.c_str());
    PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(InterfaceKey::D0),
                              "hydraulic aperture D0 [m] of interface " + i.name, &i.aperture0));
    PetscCheck(i.aperture0 > 0.0, comm, PETSC_ERR_USER_INPUT, "%sD0 = %g: must be > 0", p.c_str(),
               i.aperture0);
    PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(InterfaceKey::T1),
                              "transmissivity T1 [m/(Pa s)] between side 1 and interface " + i.name,
                              &i.transmissivity1));
    PetscCall(
        getRequiredReal(PetscOptionsObject, comm, p + key(InterfaceKey::T2),
                        "transmissivity T2 [m/(Pa s)] between interface " + i.name + " and side 2",
                        &i.transmissivity2));
    PetscCheck(i.transmissivity1 >= 0.0 && i.transmissivity2 >= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%sT1 = %g, %sT2 = %g: transmissivities must be >= 0 (0: impervious side)",
               p.c_str(), i.transmissivity1, p.c_str(), i.transmissivity2);
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
