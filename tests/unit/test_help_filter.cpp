// The -help filter (include/poroseam/help_filter.hpp) on the calls PETSc 3.18 makes: a viewer
// block is a header call and one call per form; sections start with the separator line.
#include "poroseam/help_filter.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using poroseam::HelpFilter;

namespace {

const std::string kSep = "----------------------------------------\n";

std::vector<std::string> viewerBlock(const std::string &name)
{
  return {kSep + "Viewer (-" + name + ") options:\n",
          "  -" + name +
              " ascii[:[filename][:[format][:append]]]: Prints object (PetscOptionsGetViewer)\n",
          "  -" + name +
              " binary[:[filename][:[format][:append]]]: Saves object (PetscOptionsGetViewer)\n",
          "  -" + name +
              " draw[:[drawtype][:filename|format]] Draws object (PetscOptionsGetViewer)\n",
          "  -" + name + " socket[:port]: Pushes object to a Unix socket (PetscOptionsGetViewer)\n",
          "  -" + name +
              " saws[:communicatorname]: Publishes object to SAWs (PetscOptionsGetViewer)\n"};
}

std::string run(HelpFilter &f, const std::vector<std::string> &calls)
{
  std::string out;
  for (const std::string &c : calls)
    out += f.filter(c);
  return out;
}

} // namespace

// A user's viewer inside the TS section becomes one line there, and the section goes on.
TEST(HelpFilter, ViewerInOneLineAndTheSectionGoesOn)
{
  HelpFilter f;
  std::vector<std::string> calls = {kSep + "Time stepping (TS) options:\n", "  -ts_dt <1>: step\n"};
  for (const std::string &c : viewerBlock("ts_monitor"))
    calls.push_back(c);
  calls.push_back("  -ts_max_steps <5>: steps\n");
  const std::string out = run(f, calls);
  EXPECT_EQ(out, kSep + "Time stepping (TS) options:\n  -ts_dt <1>: step\n"
                        "  -ts_monitor ascii[:file[:format]]|binary[:file]|draw|socket|saws: PETSc "
                        "viewer (PetscOptionsGetViewer)\n  -ts_max_steps <5>: steps\n");
}

// Internal viewers and sections vanish whole; what follows them is kept.
TEST(HelpFilter, InternalViewersAndSectionsDropped)
{
  HelpFilter f;
  std::vector<std::string> calls = viewerBlock("dm_fields_is_view");
  calls.push_back(kSep + "PetscDevice Options:\n");
  calls.push_back("  -device_enable <lazy>: how\n");
  calls.push_back(kSep + "poroseam output: fields and probes (-probe_<name>):\n");
  calls.push_back("  -output_fields_every <1>: every\n");
  const std::string out = run(f, calls);
  EXPECT_EQ(out, kSep + "poroseam output: fields and probes (-probe_<name>):\n"
                        "  -output_fields_every <1>: every\n");
}

// An option whose name starts like the viewer's is not one of its forms.
TEST(HelpFilter, NeighbourOptionKept)
{
  HelpFilter f;
  std::vector<std::string> calls = viewerBlock("snes_monitor");
  calls.push_back("  -snes_monitor_cancel: <FALSE : FALSE> Remove all monitors\n");
  const std::string out = run(f, calls);
  EXPECT_NE(out.find("-snes_monitor_cancel"), std::string::npos);
  EXPECT_EQ(out.find(" binary["), std::string::npos);
}
