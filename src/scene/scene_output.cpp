// The scene's output options: field and interface output (-output_fields_every,
// -output_interfaces_every) and point probes
// (-probe_<name> x,y[,z]), in their own -help section. Part of readSceneOptions.
#include "poroseam/scene.hpp"
#include "poroseam/scene_options.hpp"

#include <cmath>
#include <set>
#include <sstream>

namespace poroseam {
namespace {

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

/// Every -probe_<name> x,y[,z], in the output section.
PetscErrorCode readProbes(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, Scene &scene)
{
  char *all = nullptr;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  const std::string text = all;
  PetscCall(PetscFree(all));
  scene.probes.clear();
  for (const auto &opt : optionsWithPrefix(text, "probe_")) {
    Probe probe;
    probe.name = opt.substr(6);
    std::vector<double> x;
    bool set = false;
    PetscCall(getRealList(PetscOptionsObject, "-" + opt,
                          "point probe: " + std::to_string(scene.dim) +
                              " comma-separated coordinates [m]; time series columns " +
                              probe.name + ".ux, ...",
                          x, &set));
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

PetscErrorCode readOutputOptions(MPI_Comm comm, Scene &scene)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "poroseam output: fields and probes (-probe_<name>)", kSceneDoc);
  double every = scene.output_every;
  PetscCall(getReal(PetscOptionsObject, spec(Option::output_fields_every), &every, nullptr));
  PetscCheck(every >= 0 && every == std::floor(every), comm, PETSC_ERR_USER_INPUT,
             "-output_fields_every %g: expected a whole number >= 0", every);
  scene.output_every = (int)every;
  // Interface output: with the fields unless a scene asks for more (the caisson scenes: every
  // step, for the mobilisation of friction within a few steps).
  double interface_every = scene.output_every;
  PetscCall(getReal(PetscOptionsObject, spec(Option::output_interfaces_every), &interface_every,
                    nullptr));
  PetscCheck(interface_every >= 0 && interface_every == std::floor(interface_every), comm,
             PETSC_ERR_USER_INPUT, "-output_interfaces_every %g: expected a whole number >= 0",
             interface_every);
  scene.interface_output_every = (int)interface_every;
  PetscCall(readProbes(PetscOptionsObject, comm, scene));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

} // namespace poroseam
