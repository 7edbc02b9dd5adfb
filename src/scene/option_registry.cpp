// The table of options.def (see option_registry.hpp).
#include "poroseam/option_registry.hpp"

#include <iterator>
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

namespace {

const char *const kRegionKeys[] = {
#define POROSEAM_REGION_KEY(key) #key,
#include "poroseam/options.def"
#undef POROSEAM_REGION_KEY
};
const char *const kBoundaryKeys[] = {
#define POROSEAM_BOUNDARY_KEY(key) #key,
#include "poroseam/options.def"
#undef POROSEAM_BOUNDARY_KEY
};
const char *const kInterfaceKeys[] = {
#define POROSEAM_INTERFACE_KEY(key) #key,
#include "poroseam/options.def"
#undef POROSEAM_INTERFACE_KEY
};

template <std::size_t N> std::vector<std::string> all(const char *const (&keys)[N])
{
  return std::vector<std::string>(std::begin(keys), std::end(keys));
}

} // namespace

const char *key(RegionKey k)
{
  return kRegionKeys[static_cast<std::size_t>(k)];
}
const char *key(BoundaryKey k)
{
  return kBoundaryKeys[static_cast<std::size_t>(k)];
}
const char *key(InterfaceKey k)
{
  return kInterfaceKeys[static_cast<std::size_t>(k)];
}

std::vector<std::string> regionKeys()
{
  return all(kRegionKeys);
}
std::vector<std::string> boundaryQuantities()
{
  return all(kBoundaryKeys);
}
std::vector<std::string> interfaceKeys()
{
  return all(kInterfaceKeys);
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
