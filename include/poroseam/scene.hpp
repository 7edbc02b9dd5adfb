// A scene: everything an options file says about the model (mesh, regions, materials,
// boundary conditions, gravity, initial state, outputs). Built from PETSc options, checked
// against the mesh's Gmsh physical names; knows nothing of DMPlex.
#pragma once

#include "poroseam/time_function.hpp"
#include <array>
#include <limits>
#include <optional>
#include <petscsys.h>
#include <string>
#include <vector>

namespace poroseam {

/// A Gmsh physical group: name, dimension and tag.
struct PhysicalName {
  int dim = 0;
  int tag = 0;
  std::string name;
};

/// elastic: linear elastic solid; biot: porous, linear elastic skeleton; mohr_coulomb: porous
/// like biot, elastoplastic (Mohr-Coulomb) skeleton.
enum class MaterialModel { elastic, biot, mohr_coulomb };

struct Region {
  std::string name;
  int tag = 0; ///< value in the "Cell Sets" label
  MaterialModel model = MaterialModel::elastic;
  double young = 0.0;            ///< E [Pa]
  double poisson = 0.0;          ///< nu [-]
  double solid_density = 0.0;    ///< rho_s [kg/m3]
  double porosity = 0.0;         ///< n [-] (biot)
  double permeability = 0.0;     ///< intrinsic k [m2] (biot)
  double biot_coefficient = 1.0; ///< alpha [-] (biot)
  double storage = 0.0;          ///< 1/M [1/Pa] (biot)
  double k0 = 1.0;               ///< earth pressure coefficient at rest (geostatic state)
  double cohesion = 0.0;         ///< c [Pa] (mohr_coulomb)
  double friction_angle = 0.0;   ///< phi [degrees] (mohr_coulomb)
  double dilation_angle = 0.0;   ///< psi [degrees] (mohr_coulomb)
  double tension_cutoff = -1.0;  ///< sigma_t [Pa] (mohr_coulomb); < 0: none, the apex c / tan(phi)
  /// Part of the ground column of the geostatic state (-region_<r>_ground); unset: porous
  /// regions are ground, elastic ones are structures without initial stress.
  std::optional<bool> ground;
  /// Where k0 came from, for messages: "-region_<r>_K0 v", or "K0 = nu/(1-nu) = ... from
  /// -region_<r>_nu ..." when derived (never given: the message must say what to set).
  std::string k0_origin;
  bool porous() const
  {
    return model == MaterialModel::biot || model == MaterialModel::mohr_coulomb;
  }
  bool inGround() const { return ground.value_or(porous()); }
};

/// pressure: the pore pressure (-bc_<b>_p); normal_pressure: a load along the faces' inward
/// normal (-bc_<b>_pressure, t = -P n).
enum class BcKind { displacement, pressure, traction, flux, interface_pressure, normal_pressure };

struct BoundaryCondition {
  std::string boundary;  ///< Gmsh physical name
  int tag = 0;           ///< value in its group's label (groupLabel(support_dim))
  int support_dim = -1;  ///< the boundary's Boundary::support_dim
  BcKind kind = BcKind::displacement;
  int component = 0;         ///< displacement component (0 = x) for kind displacement
  std::vector<double> value; ///< magnitude: 1 entry, or dim entries for a traction
                             ///< (normal_pressure: P [Pa], positive pushes into the body)
  TimeFunction time = TimeFunction::step();
  std::string option; ///< the option that defined it, for messages
  bool dirichlet() const
  {
    return kind == BcKind::displacement || kind == BcKind::pressure ||
           kind == BcKind::interface_pressure;
  }
};

/// The mesh label that holds the groups of a Boundary::support_dim: "Face Sets" (-1, PETSc's
/// reader), "Vertex Sets" (0) or "Edge Sets" (1) (marked by loadGmshMesh, gmsh_mesh.cpp).
inline const char *groupLabel(int support_dim)
{
  return support_dim == 0 ? "Vertex Sets" : support_dim == 1 ? "Edge Sets" : "Face Sets";
}

struct Boundary {
  std::string name;
  int tag = 0;
  /// -1: a face group (dimension dim - 1). 0: a physical point, 1: a physical curve of a 3D
  /// mesh: a support, holding prescribed displacements only (docs/scenes.md).
  int support_dim = -1;
};

/// A zero-thickness interface: one or more Gmsh face groups split into cohesive cells.
struct Interface {
  std::string name;
  std::vector<std::string> surfaces; ///< Gmsh physical names of its faces (its named parts)
  std::vector<int> tags;             ///< their tags in "Face Sets"
  std::string side1;                 ///< region on side 1 (the normal e1 points away from it)
  int side1_tag = 0;
  double normal_stiffness = 0.0;     ///< K_N [Pa/m]
  double tangential_stiffness = 0.0; ///< K_T [Pa/m]
  double friction = 0.0;             ///< mu [-]
  double dilation = 0.0;             ///< tan(psi), psi the dilation angle (0: none)
  double dilation_slip_limit =       ///< plastic slip after which dilation stops [m]
      std::numeric_limits<double>::infinity();
  bool nodal_integration = false;    ///< Newton-Cotes/Lobatto points at the vertices
  // Hydraulics (three-node scheme, docs/physics.md section 5): present only when flow is enabled.
  bool flow = false;            ///< interface pressure p3 and its flows exist
  double aperture0 = 0.0;       ///< D0 [m], hydraulic aperture of a closed interface
  double transmissivity1 = 0.0; ///< T1 [m/(Pa s)], side 1 <-> inner (0: impervious)
  double transmissivity2 = 0.0; ///< T2 [m/(Pa s)], inner <-> side 2 (0: impervious)
};

struct Probe {
  std::string name;
  std::array<double, 3> x{{0, 0, 0}};
};

struct Scene {
  std::string mesh_file;
  double mesh_size_factor = 1.0;
  /// Order of the mesh geometry (-mesh_geometry_order): 1 straight-sided cells (the mesh's
  /// vertices only); 2 second-order Gmsh cells, curved where gmsh put their edge, face and
  /// cell nodes on a curved boundary (isoparametric with the order-2 displacement basis).
  int mesh_geometry_order = 1;
  int dim = 0; ///< from the mesh

  std::vector<Region> regions;
  std::vector<Boundary> boundaries;
  std::vector<BoundaryCondition> conditions;
  std::vector<Interface> interfaces;

  bool drained = false;           ///< no pressure unknowns anywhere
  bool axisymmetric = false;      ///< 2D meshes: x = r >= 0, y = z; quantities per full circle
  double gravity = 0.0;           ///< g [m/s2], along -y (2D) or -z (3D); 0 switches it off
  bool geostatic = false;         ///< K0 initial state
  double surface_elevation = 0.0; ///< soil surface [m] for the geostatic state
  double water_level = 0.0;       ///< phreatic level [m] for the hydrostatic pressure
  /// Boundaries the free water above the ground stands on (-water_load_boundaries): they carry
  /// its pressure rho_w g (water_level - z) for the whole run.
  std::vector<Boundary> water_load_boundaries;
  double fluid_density = 1000.0; ///< rho_w [kg/m3]
  double fluid_viscosity = 1e-3; ///< mu_w [Pa s]
  double stabilization_factor = 0.25;
  /// Order of the displacement basis (-displacement_order): 1 equal-order linear elements
  /// with the pressure stabilisation; 2 Taylor-Hood (P2/P1, Lagrange Q2/Q1), no stabilisation.
  int displacement_order = 1;

  std::string output_dir = "output";
  int output_every = 1; ///< field output every n steps, 0 for none
  /// Interface output (interfaces.h5) every n steps, 0 for none (default: output_every).
  int interface_output_every = 1;
  std::vector<Probe> probes;

  bool hasPressure() const;
  bool hasInterfacePressure() const;   ///< some interface has flow
  int regionIndexOfTag(int tag) const; ///< -1 when no region has this tag
};

/// Reads the mesh-independent part (mesh file name and size factor).
PetscErrorCode readMeshOptions(MPI_Comm comm, Scene &scene);

/// Reads everything else and checks names against the mesh's physical groups.
/// Every problem is reported as PETSC_ERR_USER_INPUT with the option and value named.
/// Each part of the scene (its lists, the physics, each region, interface and boundary, the
/// output) is a PetscOptionsBegin section: -help lists its options with their values.
PetscErrorCode readSceneOptions(MPI_Comm comm, const std::vector<PhysicalName> &names, int dim,
                                Scene &scene);

/// Reads the output options (-output_fields_every, the probes -probe_<name>); part of
/// readSceneOptions (src/scene/scene_output.cpp).
PetscErrorCode readOutputOptions(MPI_Comm comm, Scene &scene);

/// Writes the documentation of every scene option (for -help).
void printSceneHelp(MPI_Comm comm);

} // namespace poroseam
