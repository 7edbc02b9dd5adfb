#pragma once
// `poroseam -options_file <scene> -help` lists what PETSc's objects read, and PETSc's internal
// objects read a good deal no user sets: every viewer option prints a block of six lines (its
// ascii, binary, draw, socket and saws forms), and index sets, partitioners, sections and the
// mesh orientation of the interface split query viewers of their own. This filter sits between
// PETSc's help output and the terminal: it drops the sections and viewers of internal objects
// (and of PETSc features poroseam does not use: GPU devices, DMSwarm, adjoints) and shortens
// every other viewer block to one line. Everything else passes unchanged.

#include <petscsys.h>
#include <string>

namespace poroseam {

/// Pure: fed the text of each PetscHelpPrintf call in order, returns what to print for it.
class HelpFilter {
public:
  std::string filter(const std::string &text);

private:
  std::string viewer_;        ///< the viewer whose block is being shortened ("": none)
  bool skip_section_ = false; ///< inside a section that is dropped whole
};

/// Rank 0 under -help: routes PetscHelpPrintf through a HelpFilter (PETSc's hook is a global
/// function pointer without a context, so the filter's state is a file-level object).
void installHelpFilter();

} // namespace poroseam
