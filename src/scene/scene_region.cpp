// A region's options: its material (elastic, biot or mohr_coulomb), elasticity, density,
// the porous medium's parameters and the Mohr-Coulomb strength, each checked with a message
// naming the option. Part of readSceneOptions (scene.cpp), in the region's -help section.
#include "scene_parts.hpp"

#include "poroseam/scene_options.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace poroseam {

/// A region's options, in its own -help section (PetscOptionsBegin in readSceneOptions).
PetscErrorCode readRegion(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, Region &r,
                          bool drained, bool geostatic)
{
  const std::string p = "-region_" + r.name + "_";
  std::string material;
  bool set = false;
  PetscFunctionBeginUser;
  PetscCall(getString(PetscOptionsObject, p + key(RegionKey::material),
                      "material: elastic (solid only), biot (porous, with pore pressure) or "
                      "mohr_coulomb (porous, Mohr-Coulomb skeleton)",
                      material, &set));
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

  PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(RegionKey::E),
                            "Young's modulus [Pa] of region " + r.name, &r.young));
  PetscCheck(r.young > 0.0, comm, PETSC_ERR_USER_INPUT, "%sE = %g: Young's modulus must be > 0",
             p.c_str(), r.young);
  PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(RegionKey::nu),
                            "Poisson's ratio [-] of region " + r.name, &r.poisson));
  PetscCheck(r.poisson > -1.0 && r.poisson < 0.5, comm, PETSC_ERR_USER_INPUT,
             "%snu = %g: Poisson's ratio must lie in (-1, 0.5)", p.c_str(), r.poisson);
  PetscCall(getReal(PetscOptionsObject, p + key(RegionKey::rho_s),
                    "grain (or solid) density rho_s [kg/m3], >= 0 (its weight with -gravity)",
                    &r.solid_density, nullptr));
  PetscCheck(r.solid_density >= 0.0, comm, PETSC_ERR_USER_INPUT,
             "%srho_s = %g: density must be >= 0", p.c_str(), r.solid_density);
  r.k0 = r.poisson / (1.0 - r.poisson);
  bool k0_given = false;
  PetscCall(getReal(PetscOptionsObject, p + key(RegionKey::K0),
                    "earth pressure coefficient at rest K0 [-] of the geostatic state "
                    "(default nu/(1-nu))",
                    &r.k0, &k0_given));
  {
    // Messages about K0 say where it came from: a derived default was never given, so the
    // user must learn which option set it and which one to set instead.
    char origin[256];
    if (k0_given)
      std::snprintf(origin, sizeof origin, "%sK0 %g", p.c_str(), r.k0);
    else
      std::snprintf(origin, sizeof origin, "K0 = nu/(1-nu) = %g from %snu %g (%sK0 not given)",
                    r.k0, p.c_str(), r.poisson, p.c_str());
    r.k0_origin = origin;
  }
  PetscCheck(!k0_given || r.k0 >= 0.0, comm, PETSC_ERR_USER_INPUT, "%sK0 = %g: must be >= 0",
             p.c_str(), r.k0);
  {
    // Read as text so that a bad value gets our one-line message, not PETSc's trace.
    std::string ground = r.inGround() ? "true" : "false";
    PetscCall(getString(PetscOptionsObject, p + key(RegionKey::ground),
                        "part of the ground column of the geostatic state: true or false "
                        "(default: true for biot, false for elastic)",
                        ground, &set));
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
  // K0 enters only the geostatic state of the ground: a negative nu (valid) leaves a
  // negative derived K0 unused elsewhere.
  PetscCheck(k0_given || r.k0 >= 0.0 || !geostatic || !r.inGround(), comm, PETSC_ERR_USER_INPUT,
             "%s is negative: the geostatic state needs K0 >= 0; set %sK0 explicitly (the "
             "ratio of horizontal to vertical effective stress at rest)",
             r.k0_origin.c_str(), p.c_str());
  if (r.porous()) {
    PetscCall(getReal(PetscOptionsObject, p + key(RegionKey::porosity), "porosity n [-], in [0, 1)",
                      &r.porosity, nullptr));
    PetscCheck(r.porosity >= 0.0 && r.porosity < 1.0, comm, PETSC_ERR_USER_INPUT,
               "%sporosity = %g: must lie in [0, 1)", p.c_str(), r.porosity);
    if (!drained) {
      PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(RegionKey::permeability),
                                "intrinsic permeability [m2] of biot region " + r.name,
                                &r.permeability));
    } else {
      PetscCall(getReal(PetscOptionsObject, p + key(RegionKey::permeability),
                        "intrinsic permeability k [m2] (unused in a drained scene)",
                        &r.permeability, nullptr));
    }
    PetscCheck(r.permeability >= 0.0, comm, PETSC_ERR_USER_INPUT,
               "%spermeability = %g: must be >= 0", p.c_str(), r.permeability);
    PetscCall(getReal(PetscOptionsObject, p + key(RegionKey::biot_alpha),
                      "Biot coefficient alpha [-], in (0, 1]", &r.biot_coefficient, nullptr));
    PetscCheck(r.biot_coefficient > 0.0 && r.biot_coefficient <= 1.0, comm, PETSC_ERR_USER_INPUT,
               "%sbiot_alpha = %g: must lie in (0, 1]", p.c_str(), r.biot_coefficient);
    PetscCall(getReal(PetscOptionsObject, p + key(RegionKey::storage),
                      "storage 1/M [1/Pa], >= 0 (0: incompressible grains and water)", &r.storage,
                      nullptr));
    PetscCheck(r.storage >= 0.0, comm, PETSC_ERR_USER_INPUT, "%sstorage = %g: 1/M must be >= 0",
               p.c_str(), r.storage);
  }
  if (r.model == MaterialModel::mohr_coulomb) {
    // Strength of the skeleton (effective stress): c, phi, psi (non-associated when psi < phi)
    // and the optional tension cut-off on the largest principal effective stress.
    PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(RegionKey::cohesion),
                              "cohesion c [Pa] of region " + r.name, &r.cohesion));
    PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(RegionKey::friction_angle),
                              "friction angle phi [degrees] of region " + r.name,
                              &r.friction_angle));
    PetscCall(getRequiredReal(PetscOptionsObject, comm, p + key(RegionKey::dilation_angle),
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
    PetscCall(getReal(PetscOptionsObject, p + key(RegionKey::tension_cutoff),
                      "tension cut-off [Pa] on the largest principal effective stress of region " +
                          r.name + ", in [0, c / tan(phi)] (optional; none: the cone's apex)",
                      &r.tension_cutoff, &cutoff, "none"));
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

} // namespace poroseam
