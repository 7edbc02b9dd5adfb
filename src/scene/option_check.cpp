#include "poroseam/option_check.hpp"

#include "poroseam/option_registry.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>

namespace poroseam {
namespace {

/// Options of the whole scene and of the run, read by poroseam outside the families below:
/// the declared options in poroseam's namespace (options.def). -snes_reference_rtol and
/// -snes_kink_linesearch are poroseam's too but live in PETSc's namespace, where a near miss
/// may be PETSc's own.
std::vector<std::string> declaredNames()
{
  std::vector<std::string> names;
  for (const auto &s : optionRegistry())
    if (s.space == OptionSpace::poroseam) names.emplace_back(s.name());
  return names;
}

/// Options of PETSc's objects start with these: a near miss of a scene name among them is
/// left to PETSc and to the check of options nothing reads (unused_options.hpp).
const char *const kPetscPrefixes[] = {"ts_",         "snes_",  "ksp_",   "pc_",     "mat_", "vec_",
                                      "dm_",         "log_",   "malloc", "options", "mg_",  "sub_",
                                      "petsc",       "viewer", "draw",   "is_",     "sf_",  "tao_",
                                      "fieldsplit_", "help",   "info",   "version", "mpi"};

/// The splits poroseam names (src/solve/nullspace.cpp), and the splits inside each.
struct Split {
  const char *name;
  std::vector<const char *> inner;
};
const Split kSplits[] = {{"displacement", {}}, {"pressures", {"pressure", "interface_pressure"}}};
/// What follows a split's name in a solver option (its KSP, PC, matrix, inner splits, and
/// the PCs vertex_blocks of the displacement split and schur_selfp of the pressures).
const char *const kSolverParts[] = {"ksp_", "pc_",  "mat_",    "fieldsplit_", "vertex_blocks_",
                                    "mg_",  "sub_", "esteig_", "snes_",       "schur_selfp_"};

bool startsWith(const std::string &s, const std::string &prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string &s, const std::string &suffix)
{
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// How far a name may be from the one meant and still count as a misspelling of it: one
/// edit in a short name, two in a longer one, three in a long one (a quarter at most).
std::size_t tolerance(const std::string &meant)
{
  if (meant.size() <= 5) return 1;
  return meant.size() <= 12 ? 2 : 3;
}

std::string join(const std::vector<std::string> &items)
{
  std::string s;
  for (const auto &item : items)
    s += (s.empty() ? "" : ", ") + item;
  return s.empty() ? "none" : s;
}

/// The closest of `candidates` to `word` within tolerance, or "".
std::string closest(const std::string &word, const std::vector<std::string> &candidates)
{
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto &c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d <= tolerance(c) && d < best_d) best = c, best_d = d;
  }
  return best;
}

std::string suggestion(const std::string &option)
{
  return option.empty() ? "" : "; did you mean -" + option + "?";
}

/// One family of options, -<prefix><entity>_<key>: regions, boundaries, interfaces.
struct Family {
  std::string prefix;             ///< "bc_"
  std::string what;               ///< "boundary"
  std::string list;               ///< "-boundaries"
  std::vector<std::string> names; ///< the entities of the scene
  std::vector<std::string> keys;  ///< what follows an entity's name
  int mesh_dim = 0;               ///< dimension of the mesh groups it names
  std::string shown;              ///< the keys as a message lists them
};

std::vector<std::string> boundaryKeys()
{
  std::vector<std::string> keys;
  for (const auto &q : boundaryQuantities()) {
    keys.push_back(q);
    keys.push_back(q + "_ramp");
    keys.push_back(q + "_table");
  }
  return keys;
}

std::vector<Family> families(const SceneNames &names)
{
  // The keys as declared (options.def).
  const std::vector<std::string> region = regionKeys(), interface = interfaceKeys(),
                                 bc = boundaryQuantities();
  return {{"region_", "region", "-regions", names.regions, region, names.dim, join(region)},
          {"bc_", "boundary", "-boundaries", names.boundaries, boundaryKeys(), names.dim - 1,
           join(bc) + ", each with _ramp or _table"},
          {"interface_", "interface", "-interfaces", names.interfaces, interface, names.dim - 1,
           join(interface)}};
}

/// -bc_<b>_<q>_ramp and _table shape the value of -bc_<b>_<q>: without it they do nothing.
std::string checkTimeFunction(const std::string &option, const std::set<std::string> &given)
{
  for (const char *suffix : {"_ramp", "_table"})
    if (endsWith(option, suffix)) {
      const std::string base = option.substr(0, option.size() - std::string(suffix).size());
      if (!given.count(base))
        return "option -" + option + " shapes the value of -" + base +
               ", which is not given: give -" + base + " too, or drop -" + option;
    }
  return "";
}

std::string checkFamily(const Family &f, const std::string &option, const SceneNames &names,
                        const std::set<std::string> &given)
{
  const std::string rest = option.substr(f.prefix.size());
  // The entity whose name starts the option (the longest: names may hold '_').
  std::string entity;
  for (const auto &n : f.names)
    if (startsWith(rest, n + "_") && n.size() > entity.size()) entity = n;
  if (!entity.empty()) {
    const std::string key = rest.substr(entity.size() + 1);
    if (std::find(f.keys.begin(), f.keys.end(), key) != f.keys.end())
      return f.prefix == "bc_" ? checkTimeFunction(option, given) : "";
    // -bc_lid_top_uz with only 'lid' listed: the name is longer than the listed one.
    const bool longer_name = std::any_of(
        f.keys.begin(), f.keys.end(), [&](const std::string &k) { return endsWith(key, "_" + k); });
    if (!longer_name)
      return "option -" + option + ": " + f.what + " '" + entity + "' has no option '" + key +
             "' (" + f.what + " options: " + f.shown + ")" +
             suggestion(closest(key, f.keys).empty()
                            ? ""
                            : f.prefix + entity + "_" + closest(key, f.keys));
  }
  // The entity is not in the list: which one was meant? Split at a known key (the longest).
  std::string key, named;
  for (const auto &k : f.keys)
    if (endsWith(rest, "_" + k) && rest.size() > k.size() + 1 && k.size() > key.size())
      key = k, named = rest.substr(0, rest.size() - k.size() - 1);
  std::string message = "option -" + option + " names a " + f.what + " that is not in " + f.list +
                        " (" + join(f.names) + ")";
  if (key.empty()) { // neither name nor key known: the closest whole option, if any
    std::vector<std::string> all;
    for (const auto &n : f.names)
      for (const auto &k : f.keys)
        all.push_back(f.prefix + n + "_" + k);
    return message + suggestion(closest(option, all));
  }
  for (const auto &g : names.mesh_names)
    if ((g.dim == f.mesh_dim || (f.prefix == "bc_" && g.dim == 0)) && g.name == named)
      return message + ": '" + named + "' is a " + f.what + " of the mesh; add it to " + f.list;
  // One entity of its kind is the one meant whatever the spelling ("sand" for "soil").
  std::string meant = f.names.size() == 1 ? f.names[0] : closest(named, f.names);
  return message + suggestion(meant.empty() ? "" : f.prefix + meant + "_" + key);
}

/// -fieldsplit_<split>_...: the split names poroseam gives at this level (and below).
std::string checkSplit(const std::string &option, const std::string &rest,
                       const std::vector<Split> &splits)
{
  for (const auto &s : splits) {
    const std::string head = std::string(s.name) + "_";
    if (!startsWith(rest, head)) continue;
    const std::string tail = rest.substr(head.size());
    if (s.inner.empty() || !startsWith(tail, "fieldsplit_")) return "";
    std::vector<Split> inner;
    for (const char *name : s.inner)
      inner.push_back({name, {}});
    return checkSplit(option, tail.substr(std::string("fieldsplit_").size()), inner);
  }
  // Not a split of poroseam: a misspelling when a solver part follows a name close to one.
  std::string best, best_name;
  std::size_t best_d = std::string::npos;
  for (std::size_t cut = rest.find('_'); cut != std::string::npos; cut = rest.find('_', cut + 1)) {
    const std::string named = rest.substr(0, cut), tail = rest.substr(cut + 1);
    const bool solver = std::any_of(std::begin(kSolverParts), std::end(kSolverParts),
                                    [&](const char *p) { return startsWith(tail, p); });
    if (!solver) continue;
    for (const auto &s : splits) {
      const std::size_t d = editDistance(named, s.name);
      // "Clearly misspelt": at most two edits, and fewer than a third of the name.
      if (d <= 2 && 3 * d < std::string(s.name).size() && d < best_d)
        best_d = d, best_name = named,
        best = option.substr(0, option.size() - rest.size()) + s.name + "_" + tail;
    }
  }
  if (best.empty()) return "";
  std::vector<std::string> known;
  for (const auto &s : splits)
    known.emplace_back(s.name);
  return "option -" + option + ": no solver split '" + best_name +
         "' (poroseam's splits here: " + join(known) + ")" + suggestion(best);
}

/// -prbe_top 0.1,1: a probe's prefix misspelt, recognised by its value (dim coordinates).
std::string checkProbePrefix(const std::string &option, const std::string &value, int dim)
{
  const auto cut = option.find('_');
  if (cut == std::string::npos || cut + 1 >= option.size() || dim < 1) return "";
  const std::string head = option.substr(0, cut);
  if (head == "probe" || editDistance(head, "probe") > 1) return "";
  std::istringstream in(value);
  std::string item;
  int count = 0;
  while (std::getline(in, item, ',')) {
    char *end = nullptr;
    std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0') return "";
    ++count;
  }
  if (count != dim) return "";
  return "option -" + option + " is not an option of poroseam" +
         suggestion("probe_" + option.substr(cut + 1));
}

} // namespace

std::size_t editDistance(const std::string &a, const std::string &b)
{
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i)
    d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j)
    d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string closestName(const std::string &word, const std::vector<std::string> &candidates)
{
  return closest(word, candidates);
}

std::vector<std::string> sceneOptionNames()
{
  return declaredNames();
}

bool isSceneOption(const std::string &name)
{
  for (const char *prefix : {"region_", "bc_", "interface_", "probe_"})
    if (startsWith(name, prefix)) return true;
  const OptionSpec *declared = findOption(name);
  return declared && declared->space == OptionSpace::poroseam;
}

std::string misspeltOption(const std::string &name, const std::string &value,
                           const SceneNames &names, const std::set<std::string> &given)
{
  const bool scene_known = names.dim > 0;    // the mesh is read and the lists are known
  if (startsWith(name, "probe_")) return ""; // any name is a probe's name
  if (startsWith(name, "fieldsplit_"))
    return checkSplit(name, name.substr(std::string("fieldsplit_").size()),
                      std::vector<Split>(std::begin(kSplits), std::end(kSplits)));
  const std::vector<Family> all = families(names);
  for (const auto &f : all)
    if (startsWith(name, f.prefix)) return scene_known ? checkFamily(f, name, names, given) : "";
  const std::vector<std::string> scene = declaredNames();
  if (std::find(scene.begin(), scene.end(), name) != scene.end()) return "";
  for (const char *prefix : kPetscPrefixes)
    if (startsWith(name, prefix)) return "";
  const std::string meant = closest(name, scene);
  if (!meant.empty())
    return "option -" + name + " is not an option of poroseam" + suggestion(meant);
  if (!scene_known) return "";
  // A family's prefix misspelt (-regoin_soil_E, -bc_top_... as -bd_top_...): the option meant
  // must be a whole option of this scene.
  for (const auto &f : all) {
    const std::string head = f.prefix.substr(0, f.prefix.size() - 1);
    const auto cut = name.find('_');
    if (cut == std::string::npos || editDistance(name.substr(0, cut), head) > tolerance(head))
      continue;
    const std::string guess = f.prefix + name.substr(cut + 1);
    if (checkFamily(f, guess, names, given).empty())
      return "option -" + name + " is not an option of poroseam" + suggestion(guess);
  }
  return checkProbePrefix(name, value, names.dim);
}

PetscErrorCode allOptions(std::vector<std::pair<std::string, std::string>> &out)
{
  char *all = nullptr;
  PetscFunctionBeginUser;
  out.clear();
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::istringstream in(all ? all : "");
  PetscCall(PetscFree(all));
  std::string token;
  while (in >> token) {
    // A name is '-' and a letter; "-1e6" is a value.
    if (token.size() > 1 && token[0] == '-' && std::isalpha((unsigned char)token[1]))
      out.emplace_back(token.substr(1), "");
    else if (!out.empty())
      out.back().second += (out.back().second.empty() ? "" : " ") + token;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode checkOptionNames(MPI_Comm comm, const SceneNames &names)
{
  std::vector<std::pair<std::string, std::string>> options;
  std::set<std::string> given;
  PetscFunctionBeginUser;
  PetscCall(allOptions(options));
  for (const auto &o : options)
    given.insert(o.first);
  for (const auto &[name, value] : options) {
    const std::string message = misspeltOption(name, value, names, given);
    PetscCheck(message.empty(), comm, PETSC_ERR_USER_INPUT, "%s", message.c_str());
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
