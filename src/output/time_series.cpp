// timeseries.csv (split from the time loop in simulation.cpp): its columns and their units
// (timeseries.csv.units), the rows kept on a restart, and the number formats that the tests
// compare bit for bit.

#include "poroseam/time_series.hpp"

#include "file_replace.hpp"
#include "poroseam/collective_check.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

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
    // The steady pore pressure and the excess over it (docs/outputs.md).
    if (scene.hasPressure()) {
      c.push_back({p.name + ".p_steady", "Pa"});
      c.push_back({p.name + ".p_excess", "Pa"});
    }
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
  comm_ = comm;
  const std::string path = dir + "/timeseries.csv";
  path_ = path;
  std::string why; // of status 1
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
    if (status == 0 && !replaceFileContents(path, kept, &why)) status = 1;
  }
  if (rank == 0 && status == 0) {
    // Not through a symbolic link; rows go straight to the file (write(2), no stdio buffer),
    // so that a failed row can be taken back whole (see write()).
    const int fd = ::open(path.c_str(),
                          O_WRONLY | O_CREAT | O_NOFOLLOW | O_CLOEXEC |
                              (resume_step >= 0 ? O_APPEND : O_TRUNC),
                          0644);
    if (fd < 0 || !(file_ = fdopen(fd, resume_step >= 0 ? "a" : "w"))) {
      status = 1, why = std::strerror(errno);
      if (fd >= 0) ::close(fd);
    } else if (resume_step < 0) {
      why = appendRow(head + "\n");
      if (!why.empty()) status = 1;
    }
  }
  if (rank == 0 && status == 0) {
    // The unit of every column, beside the file so that readers of the CSV see no change.
    std::ostringstream out;
    out << "column,unit\n";
    for (const Column &c : columns(scene))
      out << c.name << "," << c.unit << "\n";
    if (!replaceFileContents(path + ".units", out.str(), &why)) status = 1;
  }
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, comm));
  if (status == 1) {
    close();
    PetscCall(checkOnAllRanks(comm, rank == 0 ? "cannot write " + path + ": " + why : ""));
  }
  PetscCheck(status != 2, comm, PETSC_ERR_USER_INPUT,
             "-restart: %s is missing or has other columns than this scene writes: restart "
             "with the scene of the interrupted run",
             path.c_str());
  PetscCheck(status != 3, comm, PETSC_ERR_USER_INPUT,
             "-restart: %s lacks rows up to step %d of the checkpoint", path.c_str(), resume_step);
  PetscFunctionReturn(0);
}

std::string TimeSeries::appendRow(const std::string &text)
{
  const int fd = fileno(file_);
  struct stat st;
  if (fstat(fd, &st) != 0) return std::strerror(errno);
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(n < 0 ? errno : ENOSPC);
      // Whole rows only: what part of this one reached the file goes again.
      if (ftruncate(fd, st.st_size) != 0) return why + " (and a partial row remains)";
      return why;
    }
    done += (size_t)n;
  }
  return "";
}

PetscErrorCode TimeSeries::write(const Scene &scene, const StepRow &row,
                                 const std::vector<double> &boundaries,
                                 const std::vector<double> &interfaces,
                                 const std::vector<double> &probes)
{
  PetscFunctionBeginUser;
  if (comm_ == MPI_COMM_NULL) PetscFunctionReturn(0); // not opened
  std::string error;
  if (file_) {
    std::string text;
    char number[64];
    auto add = [&](const char *format, double v) {
      std::snprintf(number, sizeof number, format, v);
      text += number;
    };
    const int dim = scene.dim;
    std::snprintf(number, sizeof number, "%d,", row.step);
    text += number;
    add("%.10e,", row.time);
    add("%.10e,", row.dt);
    add("%.6g,", row.load);
    std::snprintf(number, sizeof number, "%d,%d,%d,", row.newton, row.krylov, row.rejected);
    text += number;
    add("%.4e", row.wall);
    const int per = dim + 1 + (scene.hasInterfacePressure() ? 1 : 0);
    for (size_t b = 0; b < scene.boundaries.size(); ++b) {
      for (int d = 0; d < dim; ++d)
        add(",%.10e", boundaries[b * per + d]);
      if (scene.hasPressure()) add(",%.10e", boundaries[b * per + dim]);
      if (scene.hasInterfacePressure()) add(",%.10e", boundaries[b * per + dim + 1]);
    }
    for (double v : interfaces)
      add(",%.10e", v);
    for (size_t i = 0, k = scene.boundaries.size() * per; i < scene.interfaces.size(); ++i)
      if (scene.interfaces[i].flow) add(",%.10e", boundaries[k + i]);
    for (double v : probes)
      add(",%.12e", v);
    text += "\n";
    const std::string why = appendRow(text);
    if (!why.empty()) {
      error = "cannot write the row of step " + std::to_string(row.step) + " to " + path_ + ": " +
              why + "; the file holds every step before it";
      close();
    }
  }
  // Every rank learns whether rank 0 could: a full disk ends the run on all of them together.
  PetscCall(checkOnAllRanks(comm_, error));
  PetscFunctionReturn(0);
}

void TimeSeries::close()
{
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

} // namespace poroseam
