// The table of options.def (see option_registry.hpp).
#include "poroseam/option_registry.hpp"

#include <sstream>

namespace poroseam {

const std::vector<OptionSpec> &optionRegistry()
{
  static const std::vector<OptionSpec> all = {
// clang-format off
#define POROSEAM_OPTION(name, kind, choices, check, shown, help, doc, restart, space) \
  {"-" #name, OptionKind::kind, choices, OptionCheck::check, shown, help, doc, \
   OptionRestart::restart, OptionSpace::space},
  // clang-format on
#include "poroseam/options.def"
#undef POROSEAM_OPTION
  };
  return all;
}

const OptionSpec &spec(Option option)
{
  return optionRegistry()[static_cast<std::size_t>(option)];
}

const OptionSpec *findOption(const std::string &name)
{
  for (const auto &s : optionRegistry())
    if (name == s.name()) return &s;
  return nullptr;
}

std::vector<std::string> optionChoices(Option option)
{
  std::istringstream in(spec(option).choices);
  std::vector<std::string> values;
  for (std::string v; in >> v;)
    values.push_back(v);
  return values;
}

} // namespace poroseam
