#include "poroseam/collective_check.hpp"
#include "poroseam/curved_nodes.hpp"
#include "poroseam/external_program.hpp"
#include "poroseam/geo_check.hpp"
#include "poroseam/interfaces.hpp"
#include "poroseam/mesh.hpp"
#include "poroseam/mesh_limits.hpp"
#include "poroseam/msh_check.hpp"
#include "poroseam/partition.hpp"
#include "poroseam/reference_element.hpp"
#include "poroseam/scene_options.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <petscsf.h>
#include <sstream>
#include <sys/stat.h>

namespace poroseam {
namespace {
/// Name of the IS composed with a distributed DM: the serial point number of every point.
constexpr const char *kSerialPointNumbers = "poroseam_serial_point_numbers";
} // namespace

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

std::string factorText(double size_factor)
{
  std::ostringstream factor;
  factor.precision(17);
  factor << size_factor;
  return factor.str();
}

/// True when gmsh's log says it ran out of memory (std::bad_alloc, or its own message).
bool logSaysOutOfMemory(const std::string &log)
{
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line))
    if (line.find("bad_alloc") != std::string::npos ||
        line.find("out of memory") != std::string::npos ||
        line.find("Out of memory") != std::string::npos)
      return true;
  return false;
}

/// Runs gmsh on a .geo at a size factor, writing `msh` (MSH 2.2 ASCII); "" or what failed.
std::string runGmsh(const std::string &geo, double size_factor, const std::string &msh,
                    const std::string &log, double time_limit, int geometry_order)
{
  const std::string factor = factorText(size_factor);
  // An argument vector, no shell: paths with quotes or $(...) are only names. Order 2: gmsh
  // puts a node on every edge, quadrangle and hexahedron, on the model's curve or surface
  // where the entity lies on one (-mesh_geometry_order 2).
  ProgramEnd end;
  std::vector<std::string> args = {"gmsh",     "-3",   "-v", "1", "-format", "msh22",
                                   "-clscale", factor, "-o", msh, geo};
  if (geometry_order == 2) args.insert(args.begin() + 4, {"-order", "2"});
  const std::string why = runProgram(args, log, time_limit, &end);
  std::ostringstream limit;
  limit << time_limit;
  if (end.timed_out)
    return "gmsh was still meshing '" + geo + "' after " + limit.str() + " s (-mesh_time_limit " +
           limit.str() + ") and was stopped: a .geo with an endless " +
           "loop, or a mesh that takes longer (raise -mesh_time_limit, or give a larger " +
           "-mesh_size_factor than " + factor + "; see " + log + ")";
  // The kernel's out-of-memory killer sends SIGKILL; gmsh's own allocations throw bad_alloc
  // (then it aborts: SIGABRT, or an error exit with the message in its log).
  if (end.signal == SIGKILL || (!why.empty() && logSaysOutOfMemory(log)))
    return "out of memory while meshing '" + geo + "' at -mesh_size_factor " + factor + " (gmsh " +
           (end.signal == SIGKILL
                ? std::string("was killed by SIGKILL, the signal of the kernel's out-of-memory "
                              "killer")
                : std::string("ran out of memory")) +
           "): give a larger -mesh_size_factor (the element count grows as factor^-dim); see " +
           log;
  if (!why.empty() || !fileExists(msh))
    return "gmsh failed to mesh '" + geo + "' (" + (why.empty() ? "no mesh written" : why) +
           "; see " + log + ")";
  return "";
}

std::string formatCount(double n)
{
  std::ostringstream s;
  s.precision(n < 1e6 ? 6 : 2);
  if (n >= 1e6) s << std::scientific;
  s << std::round(n);
  return s.str();
}

/// Meshes a .geo with gmsh into work_dir; returns the .msh path or an error message. The
/// .geo (a program) is read first: commands that run programs or write files are refused
/// (geo_check.hpp). Below a size factor of 0.5 the element and node counts are estimated
/// first from a mesh at factor 1 (x factor^-dim; gmsh's -clscale scales every size), and a
/// mesh above `max_elements`, or one whose estimated memory exceeds the machine's, is refused
/// before gmsh spends minutes and gigabytes on it.
std::string meshGeometry(const std::string &geo, double size_factor, const MeshLimits &limits,
                         const std::string &work_dir, int geometry_order, std::string &msh,
                         std::string *note)
{
  std::string why = checkGeoProgram(geo);
  if (!why.empty()) return why;
  std::string stem = geo.substr(geo.find_last_of('/') + 1);
  stem = stem.substr(0, stem.size() - 4);
  std::error_code failed;
  std::filesystem::create_directories(work_dir, failed);
  if (failed) return "cannot create directory '" + work_dir + "': " + failed.message();
  msh = work_dir + "/" + stem + ".msh";
  if (size_factor < 0.5) {
    const std::string probe = work_dir + "/" + stem + ".factor1.msh";
    why = runGmsh(geo, 1.0, probe, work_dir + "/gmsh.log", limits.time_limit, 1);
    if (!why.empty()) return why;
    std::vector<PhysicalName> names;
    MshSummary s;
    why = checkGmshFile(probe, names, s);
    std::filesystem::remove(probe, failed);
    if (!why.empty()) return why;
    const double scale = std::pow(1.0 / size_factor, s.dim);
    const double estimate = (double)s.cells * scale;
    std::ostringstream f;
    f << size_factor;
    if (estimate > (double)limits.max_elements)
      return "-mesh_size_factor " + f.str() + " would make about " + formatCount(estimate) +
             " elements of dimension " + std::to_string(s.dim) + " from '" + geo + "' (" +
             std::to_string(s.cells) + " at factor 1), more than -mesh_max_elements " +
             std::to_string(limits.max_elements) + ": give a larger factor, or raise the " +
             "limit if the machine can take it";
    why = checkMeshMemory(limits, (double)s.nodes * scale, s.dim,
                          "-mesh_size_factor " + f.str() + " would make about " +
                              formatCount(estimate) + " elements from '" + geo + "'",
                          "give a larger -mesh_size_factor", note);
    if (!why.empty()) return why;
  }
  return runGmsh(geo, size_factor, msh, work_dir + "/gmsh.log", limits.time_limit, geometry_order);
}

/// The supports' labels, as "Face Sets" holds the face groups: "Vertex Sets", the vertices of
/// the physical points, and in 3D "Edge Sets", the edges of the physical curves, valued by
/// their physical tag. PETSc 3.18's reader makes neither (its -dm_plex_gmsh_mark_vertices
/// marks every vertex of every group, with one value each). A node of a point or line element
/// is the vertex with its coordinates (the same numbers of the same file; the checked file has
/// no coincident nodes). Called on the serial mesh: rank 0 holds every point.
PetscErrorCode markSupports(DM dm, const MshSummary &msh)
{
  PetscInt vStart, vEnd, cdim, dim;
  Vec coords;
  PetscSection csec;
  const PetscScalar *x;
  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, "Vertex Sets")); // on every rank: distributed with the mesh
  PetscCall(DMCreateLabel(dm, "Edge Sets"));
  PetscCall(DMGetDimension(dm, &dim));
  const bool lines = dim == 3 && !msh.lines.empty();
  if (msh.points.empty() && !lines) PetscFunctionReturn(0);
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMGetCoordinateDim(dm, &cdim));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(VecGetArrayRead(coords, &x));
  std::map<std::array<double, 3>, PetscInt> vertexAt;
  for (PetscInt v = vStart; v < vEnd; ++v) {
    PetscInt off;
    std::array<double, 3> p = {0, 0, 0};
    PetscCall(PetscSectionGetOffset(csec, v, &off));
    for (PetscInt k = 0; k < cdim; ++k)
      p[k] = PetscRealPart(x[off + k]);
    vertexAt[p] = v;
  }
  PetscCall(VecRestoreArrayRead(coords, &x));
  auto find = [&](const double *q) {
    std::array<double, 3> p = {q[0], cdim > 1 ? q[1] : 0.0, cdim > 2 ? q[2] : 0.0};
    const auto it = vertexAt.find(p);
    return it == vertexAt.end() ? (PetscInt)-1 : it->second;
  };
  for (const auto &[tag, p] : msh.points) {
    const PetscInt v = find(p.data());
    if (v >= 0) PetscCall(DMSetLabelValue(dm, "Vertex Sets", v, (PetscInt)tag));
  }
  for (const auto &[tag, ends] : lines ? msh.lines : decltype(msh.lines){}) {
    const PetscInt v[2] = {find(&ends[0]), find(&ends[3])};
    if (v[0] < 0 || v[1] < 0) continue;
    const PetscInt *join;
    PetscInt n;
    PetscCall(DMPlexGetJoin(dm, 2, v, &n, &join));
    if (n == 1) PetscCall(DMSetLabelValue(dm, "Edge Sets", join[0], (PetscInt)tag));
    PetscCall(DMPlexRestoreJoin(dm, 2, v, &n, &join));
  }
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode loadGmshMesh(MPI_Comm comm, const std::string &file, double size_factor,
                            const std::string &work_dir, DM *dm, std::vector<PhysicalName> *names,
                            int *dim, int geometry_order, int displacement_order)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  // Rank 0 checks and (for .geo) meshes the file; the outcome is broadcast as text.
  MeshLimits limits;
  PetscCall(readMeshLimits(comm, displacement_order, &limits));
  const long max_elements = limits.max_elements;
  std::string error, msh = file, note;
  std::vector<PhysicalName> found;
  MshSummary summary; // rank 0's
  if (rank == 0) {
    struct stat st;
    const std::string what = "mesh file '" + file + "' (option -mesh)";
    if (stat(file.c_str(), &st) != 0)
      error = what + " does not exist";
    else if (S_ISDIR(st.st_mode))
      error = what + " is a directory: expected a Gmsh .msh or .geo file";
    else if (!S_ISREG(st.st_mode))
      error = what + " is not a regular file: expected a Gmsh .msh or .geo file";
    else if (endsWith(file, ".geo"))
      error = meshGeometry(file, size_factor, limits, work_dir, geometry_order, msh, &note);
    else if (!endsWith(file, ".msh"))
      error = what + ": expected a Gmsh .msh or .geo file";
    // Every .msh is checked before PETSc's reader sees it (that reader trusts the file).
    if (error.empty()) error = checkGmshFile(msh, found, summary);
    // The elements' order and -mesh_geometry_order agree: no high-order node is dropped
    // silently, and a curved run has nodes to be curved by.
    if (error.empty() && summary.order == 2 && geometry_order == 1)
      error = "mesh file '" + msh + "' has second-order elements: give -mesh_geometry_order 2 " +
              "to compute with their curved geometry (with -displacement_order 2), or a " +
              "first-order mesh";
    if (error.empty() && summary.order == 1 && geometry_order == 2)
      error = "-mesh_geometry_order 2: mesh file '" + msh + "' has first-order elements " +
              "only; give a .geo (meshed with gmsh -order 2) or a second-order .msh";
    if (error.empty() && summary.cells > max_elements)
      error = "mesh file '" + msh + "' has " + std::to_string(summary.cells) +
              " elements of dimension " + std::to_string(summary.dim) +
              ", more than -mesh_max_elements " + std::to_string(max_elements) +
              " (raise the limit if the machine can take it)";
    // The memory again from the mesh itself (a .msh given, or a factor >= 0.5), before
    // PETSc reads it; the probe's estimate, when there was one, is said once.
    if (error.empty() && note.empty())
      error = checkMeshMemory(limits, (double)summary.nodes, summary.dim,
                              "mesh file '" + msh + "' has " + std::to_string(summary.cells) +
                                  " elements and " + std::to_string(summary.nodes) + " nodes",
                              endsWith(file, ".geo") ? "give a larger -mesh_size_factor"
                                                     : "give a coarser mesh",
                              &note);
    if (error.empty() && !note.empty())
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s\n", note.c_str()));
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
  // Vertex coordinates only (PETSc 3.18 would otherwise make a degree-2 coordinate field of a
  // second-order file); its edge, face and cell nodes go into a table beside (curved_nodes.hpp).
  PetscCall(readGmshFile(comm, msh.c_str(), false, dm));
  if (geometry_order == 2) PetscCall(attachCurvedNodes(comm, msh.c_str(), *dm));
  PetscCall(markSupports(*dm, summary));
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
  PetscOptionsBegin(comm, nullptr, "poroseam partitioning report", kSceneDoc);
  const OptionSpec &report_option = spec(Option::partitioner_report);
  PetscCall(PetscOptionsBool(report_option.flag, report_option.help, report_option.doc, report,
                             &report, nullptr));
  PetscOptionsEnd();
  PetscCall(configurePartitioner(*dm, kind));
  PetscSF migration = nullptr;
  PetscCall(DMPlexDistribute(*dm, 0, &migration, &dist));
  if (dist) {
    // Every point of the distributed mesh came from a point of the serial one (the migration
    // SF's root): that point's number, counted over the ranks that held the serial mesh, is
    // the point's partition-independent number (serialPointNumbers).
    PetscInt serialStart, serialEnd, pStart, pEnd, nleaves;
    const PetscInt *ilocal;
    const PetscSFNode *iremote;
    PetscMPIInt ranks;
    PetscCall(DMPlexGetChart(*dm, &serialStart, &serialEnd));
    PetscCallMPI(MPI_Comm_size(comm, &ranks));
    PetscInt held = serialEnd - serialStart;
    std::vector<PetscInt> first(ranks + 1, 0);
    PetscCallMPI(MPI_Allgather(&held, 1, MPIU_INT, first.data() + 1, 1, MPIU_INT, comm));
    for (PetscMPIInt r = 0; r < ranks; ++r)
      first[r + 1] += first[r];
    PetscCall(DMPlexGetChart(dist, &pStart, &pEnd));
    PetscCall(PetscSFGetGraph(migration, nullptr, &nleaves, &ilocal, &iremote));
    std::vector<PetscInt> number(pEnd - pStart, -1);
    for (PetscInt i = 0; i < nleaves; ++i) {
      const PetscInt p = ilocal ? ilocal[i] : i;
      if (p >= pStart && p < pEnd) number[p - pStart] = first[iremote[i].rank] + iremote[i].index;
    }
    int missing = std::count(number.begin(), number.end(), -1) > 0, any = 0;
    PetscCallMPI(MPI_Allreduce(&missing, &any, 1, MPI_INT, MPI_MAX, comm));
    PetscCheck(!any, comm, PETSC_ERR_PLIB,
               "distributeMesh: a point of the distributed mesh has no serial point");
    IS is;
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)number.size(), number.data(),
                              PETSC_COPY_VALUES, &is));
    PetscCall(PetscObjectCompose((PetscObject)dist, kSerialPointNumbers, (PetscObject)is));
    PetscCall(ISDestroy(&is));
    PetscCall(keepCurvedNodes(*dm, dist));
    PetscCall(DMDestroy(dm));
    *dm = dist;
  }
  PetscCall(PetscSFDestroy(&migration));
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

PetscErrorCode serialPointNumbers(DM dm, std::vector<PetscInt> &number)
{
  PetscInt pStart, pEnd;
  IS is = nullptr;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  number.resize(pEnd - pStart);
  PetscCall(PetscObjectQuery((PetscObject)dm, kSerialPointNumbers, (PetscObject *)&is));
  if (!is) { // not distributed (one rank): the points are the serial mesh's
    for (PetscInt p = pStart; p < pEnd; ++p)
      number[p - pStart] = p;
    PetscFunctionReturn(0);
  }
  PetscInt n;
  const PetscInt *idx;
  PetscCall(ISGetLocalSize(is, &n));
  PetscCheck(n == pEnd - pStart, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "serialPointNumbers: %" PetscInt_FMT " numbers for %" PetscInt_FMT " points", n,
             pEnd - pStart);
  PetscCall(ISGetIndices(is, &idx));
  std::copy(idx, idx + n, number.begin());
  PetscCall(ISRestoreIndices(is, &idx));
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
