#include "poroseam/help_filter.hpp"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace poroseam {

namespace {

const char kSeparator[] = "----------------------------------------\n";

/// Viewers that PETSc's internal objects query (index sets and sections made while the layout
/// is built, the partitioner, the interface submesh before it is oriented) or that belong to
/// features poroseam does not use.
const char *const kInternalViewers[] = {"is_view",
                                        "dm_fields_is_view",
                                        "global_section_view",
                                        "local_section_view",
                                        "before_orient_interface_dm_view",
                                        "petscpartitioner_view",
                                        "petscpartitioner_view_graph",
                                        "ts_dmswarm_monitor_moments",
                                        "ts_adjoint_monitor",
                                        "ts_adjoint_monitor_sensi"};

/// Sections of objects no user configures here: GPU devices (a CPU build), the small matrices
/// PETSc's finite-element set-up makes for itself, the settings of PETSc's Gmsh reader that
/// poroseam's reading of physical groups relies on ("PetscViewer options": DMPlex Gmsh).
const char *const kInternalSections[] = {
    "PetscDevice Options:", "PetscDevice host Options:", "Root PetscDeviceContext Options:",
    "Options for SEQAIJ matrix:", "PetscViewer options:"};

bool startsWith(const std::string &s, const std::string &prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

} // namespace

std::string HelpFilter::filter(const std::string &text)
{
  if (startsWith(text, kSeparator)) {
    viewer_.clear();
    skip_section_ = false;
    const std::string title = text.substr(sizeof(kSeparator) - 1);
    const std::string opening = "Viewer (-", closing = ") options:\n";
    if (startsWith(title, opening) && title.size() > opening.size() + closing.size() &&
        title.compare(title.size() - closing.size(), closing.size(), closing) == 0) {
      viewer_ = title.substr(opening.size(), title.size() - opening.size() - closing.size());
      for (const char *name : kInternalViewers)
        if (viewer_ == name) return "";
      return "  -" + viewer_ +
             " ascii[:file[:format]]|binary[:file]|draw|socket|saws: PETSc viewer "
             "(PetscOptionsGetViewer)\n";
    }
    for (const char *name : kInternalSections)
      if (title == std::string(name) + "\n") {
        skip_section_ = true;
        return "";
      }
    return text;
  }
  if (!viewer_.empty()) {
    if (startsWith(text, "  -" + viewer_ + " ")) return ""; // a form of the viewer
    viewer_.clear(); // the section the viewer was queried in goes on
  }
  return skip_section_ ? "" : text;
}

namespace {

HelpFilter help_filter; // see installHelpFilter

PetscErrorCode filteredHelpPrintf(MPI_Comm comm, const char format[], ...)
{
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::vector<char> text(n > 0 ? n + 1 : 1, '\0');
  if (n > 0) std::vsnprintf(text.data(), text.size(), format, again);
  va_end(again);
  const std::string shown = help_filter.filter(text.data());
  if (shown.empty()) return 0;
  return PetscHelpPrintfDefault(comm, "%s", shown.c_str());
}

} // namespace

void installHelpFilter()
{
  PetscHelpPrintf = filteredHelpPrintf;
}

} // namespace poroseam
