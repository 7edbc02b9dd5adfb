// The checks that take their names from the option declarations (options.def) treat every
// declared option as declared: the misspelling check accepts its name and suggests it for a near
// miss, the before-run number check refuses an overlong integer for the integer options it
// checks and leaves the others to their readers, and a restart may change exactly those
// declared so. Each is compared with the declaration's own field, not with a copy of a list.
#include "poroseam/option_check.hpp"
#include "poroseam/option_registry.hpp"
#include "poroseam/run_options.hpp"

#include "../../src/solve/restart_check.hpp"

#include <gtest/gtest.h>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace poroseam {
namespace {

TEST(OptionRegistry, NamesAreUniqueAndFound)
{
  std::set<std::string> names;
  for (const auto &s : optionRegistry()) {
    EXPECT_EQ(s.flag[0], '-');
    EXPECT_TRUE(names.insert(s.name()).second) << s.flag << " declared twice";
    EXPECT_EQ(findOption(s.name()), &s);
    EXPECT_NE(std::string(s.help), "") << s.flag;
    EXPECT_EQ(std::string(s.doc).rfind("docs/", 0), 0u) << s.flag;
  }
  EXPECT_EQ(findOption("no_such_option"), nullptr);
  EXPECT_STREQ(spec(Option::solver_auto_threshold).flag, "-solver_auto_threshold");
  EXPECT_EQ(optionChoices(Option::partitioner),
            (std::vector<std::string>{"ptscotch", "metis", "simple"}));
}

TEST(OptionRegistry, MisspellingCheckKnowsEveryDeclaredName)
{
  const SceneNames none;
  for (const auto &s : optionRegistry()) {
    const std::string name = s.name();
    EXPECT_EQ(misspeltOption(name, "1", none, {}), "") << s.flag;
    EXPECT_EQ(isSceneOption(name), s.space == OptionSpace::poroseam) << s.flag;
    if (s.space != OptionSpace::poroseam || name.size() < 8) continue;
    // -options_unused_ok shares PETSc's -options_* family, whose near misses PETSc judges.
    if (name.rfind("options_", 0) == 0) continue;
    // One letter dropped from the middle: "did you mean" the declared name.
    const std::string near = name.substr(0, name.size() / 2) + name.substr(name.size() / 2 + 1);
    const std::string message = misspeltOption(near, "1", none, {});
    EXPECT_NE(message.find("did you mean -"), std::string::npos) << near << ": " << message;
  }
  EXPECT_NE(misspeltOption("checkpoint_evry", "1", none, {}).find("-checkpoint_every?"),
            std::string::npos);
}

TEST(OptionRegistry, MisspellingCheckKnowsEveryDeclaredKey)
{
  SceneNames scene;
  scene.dim = 2;
  scene.regions = {"soil"};
  scene.boundaries = {"top"};
  scene.interfaces = {"joint"};
  const std::pair<std::string, std::vector<std::string>> families[] = {
      {"region_soil_", regionKeys()},
      {"bc_top_", boundaryQuantities()},
      {"interface_joint_", interfaceKeys()}};
  for (const auto &[prefix, keys] : families) {
    EXPECT_GE(keys.size(), 8u) << prefix;
    for (const auto &k : keys) {
      const std::set<std::string> given = {prefix + k};
      EXPECT_EQ(misspeltOption(prefix + k, "1", scene, given), "") << prefix + k;
    }
    // A key that is declared nowhere is refused, naming the family's keys.
    const std::string message = misspeltOption(prefix + "zzqq", "1", scene, {});
    EXPECT_NE(message.find("has no option 'zzqq'"), std::string::npos) << message;
    EXPECT_NE(message.find(keys.back()), std::string::npos) << message;
  }
  EXPECT_STREQ(key(RegionKey::E), "E");
  EXPECT_STREQ(key(BoundaryKey::p3), "p3");
  EXPECT_STREQ(key(InterfaceKey::dilation_limit), "dilation_limit");
}

TEST(OptionRegistry, BeforeRunCheckFollowsTheDeclarations)
{
  int integers = 0;
  for (const auto &s : optionRegistry()) {
    if (s.kind != OptionKind::integer && s.kind != OptionKind::whole_number) continue;
    const std::string error = integerRangeError(s.flag, "4294967297"); // 2^32 + 1
    if (s.check == OptionCheck::before_run) {
      ++integers;
      EXPECT_NE(error.find("out of range"), std::string::npos) << s.flag;
      EXPECT_EQ(integerRangeError(s.flag, "12"), "") << s.flag;
    } else {
      EXPECT_EQ(error, "") << s.flag << ": checked by its reader";
    }
  }
  EXPECT_GE(integers, 6); // solver_auto_threshold, checkpoint_every, restart_step, ...
  // With a solver prefix, as PETSc's own.
  EXPECT_NE(integerRangeError("-fieldsplit_displacement_ksp_max_it", "4294967297"), "");
}

TEST(OptionRegistry, RestartMayChangeFollowsTheDeclarations)
{
  for (const auto &s : optionRegistry())
    EXPECT_EQ(simulation_detail::restartMayChange(s.name()), s.restart == OptionRestart::may_change)
        << s.flag;
  // PETSc's families stay free; an option not declared is compared.
  EXPECT_TRUE(simulation_detail::restartMayChange("ksp_rtol"));
  EXPECT_TRUE(simulation_detail::restartMayChange("fieldsplit_displacement_pc_type"));
  EXPECT_FALSE(simulation_detail::restartMayChange("region_soil_E"));
  EXPECT_FALSE(simulation_detail::restartMayChange("ts_dt"));
}

} // namespace
} // namespace poroseam
