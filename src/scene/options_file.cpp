// Options files read before PETSc starts: see options_file.hpp for the rules.
#include "poroseam/options_file.hpp"

#include "poroseam/solver_preset.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

namespace poroseam {
namespace {

namespace fs = std::filesystem;

/// An options file holds a scene (a few kB): 1 MiB is far above any, and far below what
/// would exhaust memory (/dev/zero, a mesh given by mistake).
constexpr std::size_t kMaxFileBytes = 1u << 20;
/// Files that include files: a chain this deep without a cycle is no scene.
constexpr std::size_t kMaxDepth = 32;
/// Files read in all (the same file may be named twice without a cycle: files naming each
/// other's neighbours twice at each of 30 levels would read 2^30 files).
constexpr std::size_t kMaxFilesRead = 256;

bool equalsIgnoringCase(const std::string &a, const char *b)
{
  return strcasecmp(a.c_str(), b) == 0;
}

/// PETSc's test (PetscOptionsValidKey): '-' (or "--"), a letter, and not a number ("-1e4").
bool isKey(const std::string &token)
{
  if (token.size() < 2 || token[0] != '-') return false;
  const std::size_t first = token[1] == '-' ? 2 : 1;
  if (first >= token.size() || !std::isalpha((unsigned char)token[first])) return false;
  char *end = nullptr;
  std::strtod(token.c_str() + first - 1, &end);
  const char *start = token.c_str() + first - 1;
  return end == start || *end == '_' || std::isalnum((unsigned char)*end);
}

/// "a\nb" shown on one line.
std::string printable(const std::string &text)
{
  std::string shown;
  for (unsigned char c : text) {
    if (c == '\n')
      shown += "\\n";
    else if (c == '\t')
      shown += "\\t";
    else if (c == '\r')
      shown += "\\r";
    else if (c < 0x20 || c == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "\\x%02x", c);
      shown += code;
    } else
      shown += (char)c;
  }
  return shown;
}

/// Where a -options_file was named, as the error messages say it.
std::string namedBy(const std::string &where)
{
  return where == "on the command line" ? "option -options_file" : "option -options_file " + where;
}

/// Whether `text` is UTF-8: returns the offset of the first byte that is not, or npos.
std::size_t invalidUtf8(const std::string &text)
{
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = text[i];
    std::size_t n = 0;
    if (c < 0x80)
      n = 0;
    else if (c >= 0xc2 && c <= 0xdf)
      n = 1;
    else if (c >= 0xe0 && c <= 0xef)
      n = 2;
    else if (c >= 0xf0 && c <= 0xf4)
      n = 3;
    else
      return i;
    if (i + n >= text.size() && n > 0) return i;
    for (std::size_t k = 1; k <= n; ++k)
      if (((unsigned char)text[i + k] & 0xc0) != 0x80) return i;
    i += n + 1;
  }
  return std::string::npos;
}

/// One line of an options file split as PETSc splits it: the text after '#' dropped (in a
/// file), tabs and carriage returns as blanks, a token in double quotes kept whole (without
/// them).
bool tokenize(std::string line, std::vector<std::string> *tokens, bool comments = true)
{
  tokens->clear();
  const auto hash = line.find('#');
  if (comments && hash != std::string::npos) line.erase(hash);
  for (char &c : line)
    if (c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') c = ' ';
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ') {
      ++i;
      continue;
    }
    if (line[i] == '"') {
      const auto close = line.find('"', i + 1);
      if (close == std::string::npos) return false;
      tokens->push_back(line.substr(i + 1, close - i - 1));
      i = close + 1;
      continue;
    }
    const auto end = line.find(' ', i);
    tokens->push_back(line.substr(i, end == std::string::npos ? std::string::npos : end - i));
    i = end == std::string::npos ? line.size() : end;
  }
  return true;
}

/// Options whose value names an input file: relative in an options file, it is relative to
/// the folder of that file. (-output_dir and -restart name output directories: they stay
/// relative to the working directory, where the results of a run are expected.)
bool isInputPathOption(const std::string &name)
{
  if (equalsIgnoringCase(name, "-mesh")) return true;
  const std::string table = "_table";
  return name.rfind("-bc_", 0) == 0 && name.size() > table.size() + 4 &&
         name.compare(name.size() - table.size(), table.size(), table) == 0;
}

/// "solvers/direct.opts" or "options/solvers/direct.opts": the preset's name, else "".
std::string presetName(const std::string &path)
{
  const fs::path p(path);
  if (p.is_absolute() || p.extension() != ".opts") return "";
  const fs::path parent = p.parent_path();
  if (parent != "solvers" && parent != "options/solvers") return "";
  return p.stem().string();
}

class Expander {
public:
  explicit Expander(ExpandedCommandLine *out) : out_(out) {}

  /// PETSC_OPTIONS (`environment`, may be null), then argv, as PETSc inserts them (the
  /// environment first: the command line overrides it). Returns "" or the error.
  std::string commandLine(int argc, char **argv, const char *environment)
  {
    out_->args.assign(1, argc > 0 ? argv[0] : "poroseam");
    std::vector<std::string> words;
    if (environment && !tokenize(environment, &words, false))
      return "PETSC_OPTIONS: a double quote (\") is not closed";
    if (!arguments(words, "in PETSC_OPTIONS")) return error_;
    if (!arguments(std::vector<std::string>(argv + std::min(argc, 1), argv + argc),
                   "on the command line"))
      return error_;
    return "";
  }

private:
  /// Words as PetscOptionsInsertArgs walks them.
  bool arguments(const std::vector<std::string> &words, const std::string &where)
  {
    for (std::size_t i = 0; i < words.size(); ++i) {
      // PETSc skips a word that follows no option; passed on, it could become the value of
      // a flag that ends an options file read in place before it.
      if (!isKey(words[i])) continue;
      const bool has_value = i + 1 < words.size() && !isKey(words[i + 1]);
      const std::string value = has_value ? words[i + 1] : "";
      if (!option(words[i], value, has_value, where, "")) return false;
      if (has_value) ++i;
    }
    return true;
  }

  struct Open {
    std::string path;
    dev_t device;
    ino_t inode;
  };

  ExpandedCommandLine *out_;
  std::vector<Open> chain_;           ///< the files being read, outermost first
  std::vector<std::size_t> prefixes_; ///< -prefix_push: lengths of prefix_ before each push
  std::string prefix_;                ///< the prefix in force
  std::string error_;
  std::size_t files_read_ = 0;

  bool fail(const std::string &message)
  {
    error_ = message;
    return false;
  }

  /// A relative path given in the file whose folder is `folder` ("" on the command line).
  std::string resolve(const std::string &value, const std::string &folder, bool options_file)
  {
    std::error_code ec;
    if (value.empty() || fs::path(value).is_absolute()) return value;
    std::string beside = value;
    if (!folder.empty()) {
      beside = (fs::path(folder) / value).lexically_normal().string();
      if (fs::exists(beside, ec)) return beside;
      if (fs::exists(value, ec)) return value; // relative to the working directory, as before
    } else if (fs::exists(value, ec)) {
      return value;
    }
    if (options_file) {
      const std::string preset = solverPresetFile(presetName(value));
      if (!preset.empty()) return preset;
    }
    return beside; // missing: the error names the place the documentation gives
  }

  bool option(const std::string &name, const std::string &given_value, bool has_value,
              const std::string &where, const std::string &folder)
  {
    if (equalsIgnoringCase(name, "-options_file")) {
      if (!has_value || given_value.empty())
        return fail("option -options_file " + (where == "on the command line" ? "" : where + " ") +
                    "has no value: name a scene file (options/<scene>.opts)");
      return include(resolve(given_value, folder, true), given_value, where);
    }
    if (equalsIgnoringCase(name, "-options_file_yaml") ||
        equalsIgnoringCase(name, "-options_string_yaml"))
      return fail("option " + name + " " + where +
                  ": YAML options are not read by poroseam; give the options as "
                  "'-name value' lines in an -options_file");
    std::string value = given_value;
    if (equalsIgnoringCase(name, "-prefix_push")) {
      if (!has_value) return fail("option -prefix_push " + where + " has no value: name a prefix");
      prefixes_.push_back(prefix_.size());
      prefix_ += value;
    } else if (equalsIgnoringCase(name, "-prefix_pop")) {
      if (prefixes_.empty())
        return fail("option -prefix_pop " + where + " without a -prefix_push before it");
      prefix_.resize(prefixes_.back());
      prefixes_.pop_back();
    } else {
      if (has_value && !folder.empty() && isInputPathOption(name))
        value = resolve(value, folder, false);
      const std::string bare = name.substr(name[1] == '-' ? 2 : 1);
      const bool preset = std::any_of(chain_.begin(), chain_.end(),
                                      [](const Open &o) { return isSolverPresetFile(o.path); });
      out_->options.push_back({"-" + prefix_ + bare, value, has_value, where, preset});
    }
    out_->args.push_back(name);
    if (has_value) out_->args.push_back(value);
    return true;
  }

  /// Reads the options file `path` (named `as_given` by -options_file `where`) in place.
  bool include(const std::string &path, const std::string &as_given, const std::string &where)
  {
    const std::string what = "options file '" + path + "' (" + namedBy(where) + ")";
    const std::string expected = ": expected a scene file of '-name value' lines "
                                 "(options/<scene>.opts)";
    struct stat st;
    if (stat(path.c_str(), &st) != 0) {
      if (errno != ENOENT) return fail(what + " cannot be read: " + std::strerror(errno));
      std::string hint;
      const std::string preset = presetName(as_given);
      if (!preset.empty())
        hint = "; the solver presets are " + solverPresetList() + " (-solver_preset <name>)";
      else if (where.rfind("on line ", 0) == 0 && !fs::path(as_given).is_absolute())
        hint = " (a relative path in an options file is relative to that file's folder)";
      return fail(what + " does not exist" + hint);
    }
    if (S_ISDIR(st.st_mode)) return fail(what + " is a directory" + expected);
    if (S_ISFIFO(st.st_mode)) return fail(what + " is a named pipe (FIFO)" + expected);
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return fail(what + " is a device" + expected);
    if (S_ISSOCK(st.st_mode)) return fail(what + " is a socket" + expected);
    if (!S_ISREG(st.st_mode)) return fail(what + " is not a regular file" + expected);
    // Opened without blocking, and checked again: a FIFO put in its place meanwhile must not
    // hang the run either.
    const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return fail(what + " cannot be read: " + std::strerror(errno));
    struct stat opened;
    std::string text;
    bool read_failed = false;
    if (fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode)) {
      close(fd);
      return fail(what + " is not a regular file" + expected);
    }
    for (const auto &open_file : chain_)
      if (open_file.device == opened.st_dev && open_file.inode == opened.st_ino) {
        close(fd);
        std::string cycle;
        bool in_cycle = false;
        for (const auto &f : chain_) {
          in_cycle = in_cycle || (f.device == opened.st_dev && f.inode == opened.st_ino);
          if (in_cycle) cycle += "'" + f.path + "' -> ";
        }
        if (chain_.back().device == opened.st_dev && chain_.back().inode == opened.st_ino)
          return fail("options file '" + chain_.back().path + "' includes itself (" +
                      namedBy(where) + "): remove that line");
        return fail("options files include each other in a cycle: " + cycle + "'" + path + "' (" +
                    namedBy(where) + "): remove one of the -options_file lines");
      }
    if (++files_read_ > kMaxFilesRead) {
      close(fd);
      return fail(what + ": more than " + std::to_string(kMaxFilesRead) +
                  " options files read in all (a file named again and again)");
    }
    if (chain_.size() >= kMaxDepth) {
      close(fd);
      return fail(what + ": options files nested more than " + std::to_string(kMaxDepth) + " deep");
    }
    if ((std::size_t)opened.st_size > kMaxFileBytes) {
      close(fd);
      return fail(what + " has " + std::to_string((long long)opened.st_size) +
                  " bytes, more than the " + std::to_string(kMaxFileBytes) +
                  " an options file may have" + expected);
    }
    char buffer[65536];
    while (text.size() <= kMaxFileBytes) {
      const ssize_t n = read(fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) read_failed = true;
      if (n <= 0) break;
      text.append(buffer, (std::size_t)n);
    }
    close(fd);
    if (read_failed) return fail(what + " cannot be read: " + std::strerror(errno));
    if (text.size() > kMaxFileBytes)
      return fail(what + " has more than the " + std::to_string(kMaxFileBytes) +
                  " bytes an options file may have" + expected);
    const auto nul = text.find('\0');
    if (nul != std::string::npos)
      return fail(what + " is not a text file (a NUL byte at byte " + std::to_string(nul + 1) +
                  ")" + expected);
    const auto bad = invalidUtf8(text);
    if (bad != std::string::npos) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02x", (unsigned char)text[bad]);
      const long line = 1 + (long)std::count(text.begin(), text.begin() + bad, '\n');
      return fail(what + " is not UTF-8 text (byte " + code + " on line " + std::to_string(line) +
                  ")" + expected);
    }
    chain_.push_back({path, opened.st_dev, opened.st_ino});
    const bool ok = lines(path, text);
    chain_.pop_back();
    return ok;
  }

  bool lines(const std::string &path, const std::string &text)
  {
    const std::string folder = fs::path(path).parent_path().string();
    std::vector<std::string> tokens;
    std::size_t start = 0;
    for (long number = 1; start < text.size(); ++number) {
      auto end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      const std::string line = text.substr(start, end - start);
      start = end + 1;
      const std::string where = "on line " + std::to_string(number) + " of '" + path + "'";
      const std::string at = "options file '" + path + "' line " + std::to_string(number) + ": ";
      if (!tokenize(line, &tokens)) return fail(at + "a double quote (\") is not closed");
      if (tokens.empty()) continue;
      const std::string &name = tokens[0];
      if (equalsIgnoringCase(name, "alias"))
        return fail(at + "'alias' lines are not read by poroseam: give the option by its name");
      if (!isKey(name))
        return fail(at + "'" + printable(name) +
                    "' is not an option (an option is '-' and a letter, then its value)");
      if (tokens.size() > 1 && isKey(tokens[1]))
        return fail(at + "two options on one line (" + name + " " + tokens[1] +
                    "): one option per line");
      if (tokens.size() > 2)
        return fail(at + "'" + printable(tokens[2]) + "' after the value of " + name +
                    ": one value per option (a value with spaces goes in double quotes)");
      if (!option(name, tokens.size() > 1 ? tokens[1] : "", tokens.size() > 1, where, folder))
        return false;
    }
    return true;
  }
};

} // namespace

std::string expandOptionsFiles(int argc, char **argv, const char *environment,
                               ExpandedCommandLine *out)
{
  Expander expander(out);
  return expander.commandLine(argc, argv, environment);
}

std::vector<std::string> startedCommandLine(const std::vector<std::string> &fallback)
{
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in || all.empty()) return fallback;
  std::vector<std::string> args;
  std::size_t start = 0;
  while (start < all.size()) {
    const auto end = all.find('\0', start);
    args.push_back(all.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return args;
}

} // namespace poroseam
