#include "poroseam/collective_check.hpp"
#include "poroseam/external_program.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/partition.hpp"
#include "poroseam/reference_element.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/stat.h>

namespace poroseam {
namespace {

bool fileExists(const std::string &path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

bool endsWith(const std::string &s, const std::string &suffix)
{
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Reads the $PhysicalNames block of a Gmsh file: lines `dim tag "name"`.
std::string readPhysicalNames(const std::string &path, std::vector<PhysicalName> &names)
{
  std::ifstream in(path);
  if (!in) return "cannot open mesh file '" + path + "'";
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (first && line.rfind("$MeshFormat", 0) != 0)
      return "mesh file '" + path + "' is not a Gmsh ASCII .msh file (no $MeshFormat header)";
    first = false;
    if (line.rfind("$PhysicalNames", 0) != 0) continue;
    int count = 0;
    std::getline(in, line);
    std::istringstream(line) >> count;
    for (int i = 0; i < count && std::getline(in, line); ++i) {
      PhysicalName n;
      std::istringstream fields(line);
      fields >> n.dim >> n.tag;
      const auto a = line.find('"'), b = line.rfind('"');
      if (a == std::string::npos || b <= a)
        return "mesh file '" + path + "': bad $PhysicalNames line";
      n.name = line.substr(a + 1, b - a - 1);
      names.push_back(n);
    }
    return "";
  }
  return "mesh file '" + path +
         "' has no $PhysicalNames: name the regions and boundaries as Gmsh physical groups";
}

/// Meshes a .geo with gmsh into work_dir; returns the .msh path or an error message.
std::string meshGeometry(const std::string &geo, double size_factor, const std::string &work_dir,
                         std::string &msh)
{
  std::string stem = geo.substr(geo.find_last_of('/') + 1);
  stem = stem.substr(0, stem.size() - 4);
  std::error_code failed;
  std::filesystem::create_directories(work_dir, failed);
  if (failed) return "cannot create directory '" + work_dir + "': " + failed.message();
  msh = work_dir + "/" + stem + ".msh";
  std::ostringstream factor;
  factor.precision(17);
  factor << size_factor;
  const std::string log = work_dir + "/gmsh.log";
  const std::string why = runProgram(
      {"gmsh", "-3", "-v", "1", "-format", "msh22", "-clscale", factor.str(), "-o", msh, geo}, log);
  if (!why.empty() || !fileExists(msh))
    return "gmsh failed to mesh '" + geo + "' (" + (why.empty() ? "no mesh written" : why) +
           "; see " + log + ")";
  return "";
}

} // namespace

PetscErrorCode loadGmshMesh(MPI_Comm comm, const std::string &file, double size_factor,
                            const std::string &work_dir, DM *dm, std::vector<PhysicalName> *names,
                            int *dim)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  // Rank 0 checks and (for .geo) meshes the file; the outcome is broadcast as text.
  std::string error, msh = file;
  std::vector<PhysicalName> found;
  if (rank == 0) {
    if (!fileExists(file))
      error = "mesh file '" + file + "' (option -mesh) does not exist";
    else if (endsWith(file, ".geo"))
      error = meshGeometry(file, size_factor, work_dir, msh);
    else if (!endsWith(file, ".msh"))
      error = "mesh file '" + file + "' (option -mesh): expected a Gmsh .msh or .geo file";
    if (error.empty()) error = readPhysicalNames(msh, found);
  }
  std::ostringstream packed;
  packed << error.size() << '\n' << error << '\n' << msh << '\n' << found.size() << '\n';
  for (const auto &n : found)
    packed << n.dim << ' ' << n.tag << ' ' << n.name << '\n';
  std::string text = packed.str();
  int length = (int)text.size();
  PetscCallMPI(MPI_Bcast(&length, 1, MPI_INT, 0, comm));
  text.resize(length);
  PetscCallMPI(MPI_Bcast(text.data(), length, MPI_CHAR, 0, comm));
  std::istringstream in(text);
  size_t elen = 0, count = 0;
  in >> elen;
  in.get();
  error.assign(elen, ' ');
  in.read(error.data(), elen);
  in.get();
  std::getline(in, msh);
  PetscCheck(error.empty(), comm, PETSC_ERR_USER_INPUT, "%s", error.c_str());
  in >> count;
  names->clear();
  for (size_t i = 0; i < count; ++i) {
    PhysicalName n;
    in >> n.dim >> n.tag;
    in.get();
    std::getline(in, n.name);
    names->push_back(n);
  }
  PetscCall(DMPlexCreateGmshFromFile(comm, msh.c_str(), PETSC_TRUE, dm));
  PetscInt d;
  PetscCall(DMGetDimension(*dm, &d));
  *dim = (int)d;
  PetscCall(PetscObjectSetName((PetscObject)*dm, "mesh"));
  PetscFunctionReturn(0);
}

PetscErrorCode distributeMesh(DM *dm)
{
  DM dist = nullptr;
  MPI_Comm comm;
  PetscMPIInt size;
  PartitionerKind kind;
  std::string kindName;
  PetscBool report = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)*dm, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(readPartitionerOption(comm, &kind, &kindName));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-partitioner_report", &report, nullptr));
  PetscCall(configurePartitioner(*dm, kind));
  PetscCall(DMPlexDistribute(*dm, 0, nullptr, &dist));
  if (dist) {
    PetscCall(DMDestroy(dm));
    *dm = dist;
  }
  if (report) { // cells per rank and cohesive cells apart from a bulk neighbour
    PetscInt cStart, cEnd, separated, total;
    PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
    PetscCall(countSeparatedCohesiveCells(*dm, &separated, &total));
    long mine = (long)(cEnd - cStart);
    std::vector<long> cells(size, 0);
    PetscCallMPI(MPI_Gather(&mine, 1, MPI_LONG, cells.data(), 1, MPI_LONG, 0, comm));
    std::ostringstream line;
    line << "partition: " << kindName << ", " << size << " rank" << (size > 1 ? "s" : "")
         << ", cells per rank";
    for (long n : cells)
      line << ' ' << n;
    line << "; cohesive cells with a bulk neighbour on another rank: " << separated << " of "
         << total << '\n';
    PetscCall(PetscPrintf(comm, "%s", line.str().c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkCellOrientation(DM dm)
{
  PetscInt cStart, cEnd, dim;
  MPI_Comm comm;
  std::map<int, ReferenceElement> elements;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  Vec coords;
  PetscSection csec;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  char message[512] = "";
  for (PetscInt c = cStart; c < cEnd && !message[0]; ++c) {
    DMPolytopeType ct;
    PetscCall(DMPlexGetCellType(dm, c, &ct));
    if (DMPolytopeTypeGetDim(ct) != dim || isCohesive(ct)) continue;
    if (!elements.count(ct)) PetscCall(ReferenceElement::create(ct, &elements[ct]));
    const ReferenceElement &e = elements[ct];
    PetscScalar *x = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm, csec, coords, c, &n, &x));
    PointGeometry g;
    for (int q = 0; q < e.num_quadrature; ++q) {
      if (mapQuadraturePoint(e, x, q, g) <= 0.0) {
        double centroid[3] = {0, 0, 0};
        for (int a = 0; a < e.num_vertices; ++a)
          for (int k = 0; k < dim; ++k)
            centroid[k] += x[a * dim + k] / e.num_vertices;
        PetscCall(PetscSNPrintf(message, sizeof(message),
                                "inverted element: %s cell %d with centroid (%g, %g, %g) has a "
                                "non-positive Jacobian determinant; fix its node order in the mesh",
                                DMPolytopeTypes[ct], (int)c, centroid[0], centroid[1],
                                centroid[2]));
        break;
      }
    }
    PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, c, &n, &x));
  }
  PetscCall(checkOnAllRanks(comm, message)); // every rank stops, with the bad cell named
  PetscFunctionReturn(0);
}

} // namespace poroseam
