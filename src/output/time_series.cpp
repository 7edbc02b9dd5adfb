// timeseries.csv (split from the time loop in simulation.cpp): its columns and their units
// (timeseries.csv.units), the rows kept on a restart, and the number formats that the tests
// compare bit for bit.

#include "poroseam/time_series.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace poroseam {

std::vector<TimeSeries::Column> TimeSeries::columns(const Scene &scene)
{
  std::vector<Column> c;
  const char *axis[3] = {"x", "y", "z"};
  // Plane strain: forces and flows per metre out of plane; axisymmetric: the full circle.
  const bool per_metre = scene.dim == 2 && !scene.axisymmetric;
  const std::string force = per_metre ? "N/m" : "N", flow = per_metre ? "m2/s" : "m3/s",
                    volume = per_metre ? "m2" : "m3";
  c = {{"step", "1"},       {"time", "s"},    {"dt", "s"},       {"load", "1"},
       {"newton_its", "1"}, {"ksp_its", "1"}, {"rejected", "1"}, {"wall_time", "s"}};
  for (const auto &b : scene.boundaries) {
    for (int d = 0; d < scene.dim; ++d)
      c.push_back({b.name + ".F" + axis[d], force});
    if (scene.hasPressure()) c.push_back({b.name + ".flux", flow});
    if (scene.hasInterfacePressure()) c.push_back({b.name + ".interface_outflow", flow});
  }
  // Interface blocks as interfaceResultants writes them, then the interface outflows.
  auto block = [&](const Interface &i, const std::string &name) {
    for (int d = 0; d < scene.dim; ++d)
      c.push_back({name + ".F" + axis[d], force});
    if (i.flow) {
      c.push_back({name + ".flux1", flow});
      c.push_back({name + ".flux2", flow});
      c.push_back({name + ".storage", volume});
      c.push_back({name + ".storage_rate", flow});
      c.push_back({name + ".p3_force", force});
    }
  };
  for (const auto &i : scene.interfaces) {
    block(i, i.name);
    if (i.surfaces.size() > 1)
      for (const auto &s : i.surfaces)
        block(i, i.name + "." + s);
  }
  for (const auto &i : scene.interfaces)
    if (i.flow) c.push_back({i.name + ".outflow", flow});
  for (const auto &p : scene.probes) {
    for (int d = 0; d < scene.dim; ++d)
      c.push_back({p.name + ".u" + axis[d], "m"});
    c.push_back({p.name + ".p", "Pa"});
  }
  return c;
}

std::string TimeSeries::header(const Scene &scene)
{
  std::string h;
  for (const Column &c : columns(scene))
    h += (h.empty() ? "" : ",") + c.name;
  return h;
}

PetscErrorCode TimeSeries::open(MPI_Comm comm, const Scene &scene, const std::string &dir,
                                int resume_step)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  close();
  const std::string path = dir + "/timeseries.csv";
  const std::string head = header(scene);
  // 0: fine, 1: cannot write, 2: missing or other columns, 3: rows missing (restart)
  int status = 0;
  if (rank == 0 && resume_step >= 0) {
    std::ifstream in(path);
    std::string line, kept;
    int rows = 0;
    if (!std::getline(in, line) || line != head) status = 2;
    kept = line + "\n";
    while (status == 0 && std::getline(in, line)) {
      const int step = std::atoi(line.c_str());
      if (step > resume_step) break;
      kept += line + "\n", ++rows;
    }
    if (status == 0 && rows != resume_step + 1) status = 3;
    if (status == 0) {
      std::ofstream out(path + ".tmp", std::ios::trunc);
      out << kept;
      out.close();
      std::error_code failed;
      if (out) std::filesystem::rename(path + ".tmp", path, failed);
      if (!out || failed) status = 1;
    }
  }
  if (rank == 0 && status == 0) {
    file_ = std::fopen(path.c_str(), resume_step >= 0 ? "a" : "w");
    if (!file_)
      status = 1;
    else if (resume_step < 0)
      std::fprintf(file_, "%s\n", head.c_str());
  }
  if (rank == 0 && status == 0) {
    // The unit of every column, beside the file so that readers of the CSV see no change.
    std::ofstream out(path + ".units.tmp", std::ios::trunc);
    out << "column,unit\n";
    for (const Column &c : columns(scene))
      out << c.name << "," << c.unit << "\n";
    out.close();
    std::error_code failed;
    if (out) std::filesystem::rename(path + ".units.tmp", path + ".units", failed);
    if (!out || failed) status = 1;
  }
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
  PetscCheck(status != 1, comm, PETSC_ERR_FILE_OPEN, "cannot write %s (option -output_dir)",
             path.c_str());
  PetscCheck(status != 2, comm, PETSC_ERR_USER_INPUT,
             "-restart: %s is missing or has other columns than this scene writes: restart "
             "with the scene of the interrupted run",
             path.c_str());
  PetscCheck(status != 3, comm, PETSC_ERR_USER_INPUT,
             "-restart: %s lacks rows up to step %d of the checkpoint", path.c_str(), resume_step);
  PetscFunctionReturn(0);
}

void TimeSeries::write(const Scene &scene, const StepRow &row,
                       const std::vector<double> &boundaries, const std::vector<double> &interfaces,
                       const std::vector<double> &probes)
{
  if (!file_) return;
  const int dim = scene.dim;
  std::fprintf(file_, "%d,%.10e,%.10e,%.6g,%d,%d,%d,%.4e", row.step, row.time, row.dt, row.load,
               row.newton, row.krylov, row.rejected, row.wall);
  const int per = dim + 1 + (scene.hasInterfacePressure() ? 1 : 0);
  for (size_t b = 0; b < scene.boundaries.size(); ++b) {
    for (int d = 0; d < dim; ++d)
      std::fprintf(file_, ",%.10e", boundaries[b * per + d]);
    if (scene.hasPressure()) std::fprintf(file_, ",%.10e", boundaries[b * per + dim]);
    if (scene.hasInterfacePressure()) std::fprintf(file_, ",%.10e", boundaries[b * per + dim + 1]);
  }
  for (double v : interfaces)
    std::fprintf(file_, ",%.10e", v);
  for (size_t i = 0, k = scene.boundaries.size() * per; i < scene.interfaces.size(); ++i)
    if (scene.interfaces[i].flow) std::fprintf(file_, ",%.10e", boundaries[k + i]);
  for (double v : probes)
    std::fprintf(file_, ",%.12e", v);
  std::fprintf(file_, "\n");
  std::fflush(file_);
}

void TimeSeries::close()
{
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

} // namespace poroseam
