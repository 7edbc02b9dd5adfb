// Values of PETSc's choice options against PETSc's own lists: see petsc_choices.hpp.
#include "poroseam/petsc_choices.hpp"

#include "poroseam/option_check.hpp"

#include <petscts.h>
#include <strings.h>

namespace poroseam {
namespace {

/// Whether `option` is `base` or `<prefix>_base` (-fieldsplit_displacement_pc_type).
bool matches(const std::string &option, const std::string &base)
{
  if (option == base) return true;
  return option.size() > base.size() + 1 &&
         option.compare(option.size() - base.size(), base.size(), base) == 0 &&
         option[option.size() - base.size() - 1] == '_';
}

std::vector<std::string> registered(PetscFunctionList list)
{
  std::vector<std::string> names;
  const char **array = nullptr;
  int n = 0;
  if (PetscFunctionListGet(list, &array, &n)) return names;
  for (int i = 0; i < n; ++i) // n counts the null that ends the array too
    if (array[i]) names.emplace_back(array[i]);
  PetscFree(array);
  return names;
}

/// PETSc's enum tables end with the type's name, the prefix of its values, and a null.
std::vector<std::string> enumNames(const char *const *table)
{
  std::vector<std::string> names;
  int n = 0;
  while (table[n])
    ++n;
  for (int i = 0; i + 2 < n; ++i)
    names.emplace_back(table[i]);
  for (auto &name : names)
    for (char &c : name)
      c = (char)std::tolower((unsigned char)c);
  return names;
}

/// The direct solver packages this PETSc was built with that factor AIJ matrices.
std::vector<std::string> solverPackages()
{
  // MatSolverType has no list to walk: ask for each package PETSc can be built with.
  static const char *const known[] = {
      "petsc",  "mumps",     "superlu",     "superlu_dist", "umfpack",  "cholmod", "klu",
      "pastix", "strumpack", "mkl_pardiso", "mkl_cpardiso", "cusparse", "essl",    "lusol",
      "spqr",   "elemental", "scalapack",   "bas",          "matlab"};
  std::vector<std::string> found;
  for (const char *type : known)
    for (MatFactorType factor : {MAT_FACTOR_LU, MAT_FACTOR_CHOLESKY, MAT_FACTOR_ILU}) {
      PetscBool has_type = PETSC_FALSE, has_matrix = PETSC_FALSE;
      if (!MatSolverTypeGet(type, MATSEQAIJ, factor, &has_type, &has_matrix, nullptr) && has_type) {
        found.emplace_back(type);
        break;
      }
    }
  return found;
}

} // namespace

bool petscChoices(const std::string &name, PetscChoices *choices)
{
  std::vector<std::string> *values = &choices->values;
  std::string *what = &choices->what;
  choices->ignore_case = false;
  struct Registry {
    const char *base, *what;
    PetscFunctionList *list;
  };
  const Registry registries[] = {
      {"ts_type", "time stepping method of PETSc (TSType)", &TSList},
      {"snes_type", "nonlinear solver of PETSc (SNESType)", &SNESList},
      {"snes_linesearch_type", "line search of PETSc (SNESLineSearchType)", &SNESLineSearchList},
      {"ksp_type", "Krylov method of PETSc (KSPType)", &KSPList},
      {"pc_type", "preconditioner of PETSc or poroseam (PCType)", &PCList},
      {"pc_factor_mat_ordering_type", "matrix ordering of PETSc (MatOrderingType)",
       &MatOrderingList}};
  for (const auto &r : registries)
    if (matches(name, r.base)) {
      *values = registered(*r.list);
      *what = r.what;
      return true;
    }
  struct Table {
    const char *base, *what;
    const char *const *table;
  };
  const Table tables[] = {
      {"pc_fieldsplit_type", "way of combining the splits (PCCompositeType)", PCCompositeTypes},
      {"pc_fieldsplit_schur_fact_type", "Schur factorization (PCFieldSplitSchurFactType)",
       PCFieldSplitSchurFactTypes},
      {"pc_fieldsplit_schur_precondition",
       "Schur complement preconditioning (PCFieldSplitSchurPreType)", PCFieldSplitSchurPreTypes},
      {"pc_asm_type", "additive Schwarz variant (PCASMType)", PCASMTypes},
      {"pc_mg_type", "multigrid form (PCMGType)", PCMGTypes},
      {"pc_mg_cycle_type", "multigrid cycle (PCMGCycleType)", PCMGCycleTypes},
      {"ksp_norm_type", "Krylov residual norm (KSPNormType)", KSPNormTypes},
      {"ts_exact_final_time", "final time handling (TSExactFinalTimeOption)",
       TSExactFinalTimeOptions}};
  for (const auto &t : tables)
    if (matches(name, t.base)) {
      *values = enumNames(t.table);
      *what = t.what;
      choices->ignore_case = true; // PetscEnumFind
      return true;
    }
  if (matches(name, "pc_hypre_type")) {
    // PCSetFromOptions_HYPRE's list (PETSc 3.18, src/ksp/pc/impls/hypre/hypre.c), not exported.
    *values = {"euclid", "pilut", "parasails", "boomeramg", "ams", "ads"};
    *what = "hypre preconditioner";
    choices->ignore_case = true; // PetscEListFind
    return true;
  }
  if (matches(name, "pc_factor_mat_solver_type")) {
    *values = solverPackages();
    *what = "direct solver package of this PETSc (MatSolverType)";
    return true;
  }
  return false;
}

PetscErrorCode checkPetscChoices(MPI_Comm comm)
{
  std::vector<std::pair<std::string, std::string>> options;
  PetscFunctionBeginUser;
  // The registries fill as their package starts: start them all now.
  PetscCall(TSInitializePackage());
  PetscCall(SNESInitializePackage());
  PetscCall(KSPInitializePackage());
  PetscCall(PCInitializePackage());
  PetscCall(MatInitializePackage());
  PetscCall(allOptions(options));
  for (const auto &[name, value] : options) {
    PetscChoices c;
    if (value.empty() || !petscChoices(name, &c) || c.values.empty()) continue;
    bool known = false;
    for (const auto &v : c.values)
      known = known || (c.ignore_case ? strcasecmp(v.c_str(), value.c_str()) == 0 : v == value);
    if (known) continue;
    std::string list;
    const std::string meant = closestName(value, c.values);
    for (const auto &v : c.values)
      list += (list.empty() ? "" : ", ") + v;
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "option -%s %s: not a %s; expected one of %s%s",
            name.c_str(), value.c_str(), c.what.c_str(), list.c_str(),
            meant.empty() ? "" : (" (did you mean " + meant + "?)").c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
