#include "poroseam/auto_threshold.hpp"

#include "poroseam/option_registry.hpp"
#include "poroseam/solver_preset.hpp"

namespace poroseam {

PetscErrorCode readAutoThreshold(PetscOptionItems *PetscOptionsObject, MPI_Comm comm,
                                 int displacement_order, PetscInt *threshold)
{
  const OptionSpec &option = spec(Option::solver_auto_threshold);
  PetscFunctionBeginUser;
  *threshold = defaultAutoThreshold(displacement_order);
  if (PetscOptionsObject)
    PetscCall(
        PetscOptionsInt(option.flag, option.help, option.doc, *threshold, threshold, nullptr));
  else
    PetscCall(PetscOptionsGetInt(nullptr, nullptr, option.flag, threshold, nullptr));
  PetscCheck(*threshold >= 0, comm, PETSC_ERR_USER_INPUT,
             "%s %" PetscInt_FMT ": expected a number of unknowns >= 0", option.flag, *threshold);
  PetscFunctionReturn(0);
}

} // namespace poroseam
