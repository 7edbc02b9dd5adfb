#include "poroseam/geo_check.hpp"

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <vector>

namespace poroseam {
namespace {

/// gmsh's commands that run a program: its parser compares the command word with these
/// (Gmsh.y: "SystemCall", "System", "NonBlockingSystemCall"; OnelabRun starts a client).
/// "Shell" is no gmsh command today; refused so a future one is not let through.
const char *const kRunsProgram[] = {"SystemCall", "System", "NonBlockingSystemCall", "OnelabRun",
                                    "Shell"};
/// Commands that write or remove files where the .geo says (outside the output directory).
const char *const kWritesFiles[] = {"Save", "Print", "CreateDir", "DeleteFile", "SendToServer"};
/// Commands that read another file as gmsh input: that file is a program too.
const char *const kReadsFile[] = {"Include", "Merge", "MergeWithBoundingBox", "ShapeFromFile"};

constexpr int kMaxDepth = 16;

struct Token {
  enum Kind { word, string, symbol } kind;
  std::string text;
  long line;
};

/// gmsh's lexer (Gmsh.l): "//" to the end of the line and "/* */" are comments, strings are
/// "..." with backslash escapes. Anything else is code; words are [A-Za-z_][A-Za-z0-9_]*.
std::vector<Token> tokenize(const std::string &s)
{
  std::vector<Token> out;
  long line = 1;
  size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == '\n') {
      ++line, ++i;
    } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
      while (i < s.size() && s[i] != '\n')
        ++i;
    } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
      i += 2;
      while (i < s.size() && !(s[i] == '*' && i + 1 < s.size() && s[i + 1] == '/'))
        line += s[i++] == '\n';
      i += 2;
    } else if (c == '"') {
      const long at = line;
      std::string text;
      ++i;
      while (i < s.size() && s[i] != '"') {
        if (s[i] == '\\' && i + 1 < s.size()) text += s[i++];
        line += s[i] == '\n';
        text += s[i++];
      }
      ++i;
      out.push_back({Token::string, text, at});
    } else if (std::isalpha((unsigned char)c) || c == '_') {
      const size_t start = i;
      while (i < s.size() && (std::isalnum((unsigned char)s[i]) || s[i] == '_'))
        ++i;
      out.push_back({Token::word, s.substr(start, i - start), line});
    } else {
      if (!std::isspace((unsigned char)c)) out.push_back({Token::symbol, std::string(1, c), line});
      ++i;
    }
  }
  return out;
}

bool among(const std::string &w, const char *const *list, size_t n)
{
  for (size_t k = 0; k < n; ++k)
    if (w == list[k]) return true;
  return false;
}

std::string directoryOf(const std::string &path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

class GeoScanner {
public:
  explicit GeoScanner(const std::string &top) : top_(top) {}

  std::string scan(const std::string &path, const std::string &named_by, int depth)
  {
    const std::string where = path == top_ ? "mesh file '" + top_ + "' (option -mesh)"
                                           : "file '" + path + "' (" + named_by + ")";
    if (depth > kMaxDepth)
      return where + ": Include/Merge nested deeper than " + std::to_string(kMaxDepth) +
             " files (a file that includes itself?)";
    struct stat st;
    if (stat(path.c_str(), &st) != 0) return where + " does not exist";
    if (!S_ISREG(st.st_mode)) return where + " is not a regular file";
    if (!visited_.insert(path).second) return ""; // scanned already (gmsh will loop, not us)
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) return where + ": cannot be read";
    const std::vector<Token> t = tokenize(text.str());
    const std::string refuse = "; a .geo is a program run by gmsh, and poroseam runs only .geo "
                               "files that do not run programs or write files (docs/scenes.md, "
                               "Mesh): remove the command or mesh the file yourself and give the "
                               ".msh";
    for (size_t k = 0; k < t.size(); ++k) {
      if (t[k].kind != Token::word) continue;
      const std::string &w = t[k].text;
      const std::string at = where + ", line " + std::to_string(t[k].line) + ": ";
      if (among(w, kRunsProgram, std::size(kRunsProgram)))
        return at + "'" + w + "' runs a program" + refuse;
      if (among(w, kWritesFiles, std::size(kWritesFiles)))
        return at + "'" + w + "' writes or removes a file" + refuse;
      if (w == "Printf" || w == "Sprintf") { // Printf(...) > "file" appends to a file
        size_t j = k + 1;
        int depth_paren = 0;
        for (; j < t.size(); ++j) {
          if (t[j].kind != Token::symbol) continue;
          if (t[j].text == "(") ++depth_paren;
          if (t[j].text == ")" && --depth_paren <= 0) break;
          if (t[j].text == ";") break;
        }
        if (j + 1 < t.size() && t[j + 1].kind == Token::symbol && t[j + 1].text == ">")
          return at + "'" + w + "(...) >' writes a file" + refuse;
      }
      if (among(w, kReadsFile, std::size(kReadsFile))) {
        // Include "file"; Merge "file"; ShapeFromFile("file"): one literal string, then ; or )
        size_t j = k + 1;
        if (j < t.size() && t[j].kind == Token::symbol && t[j].text == "(") ++j;
        const bool literal = j + 1 < t.size() && t[j].kind == Token::string &&
                             t[j + 1].kind == Token::symbol &&
                             (t[j + 1].text == ";" || t[j + 1].text == ")");
        if (!literal)
          return at + "'" + w + "' with a file name that is not one literal \"string\": " +
                 "poroseam checks every file a .geo reads before gmsh runs it, so it must " +
                 "know the name";
        std::string target = t[j].text;
        if (target.empty() || target[0] != '/') target = directoryOf(path) + "/" + target;
        const std::string why =
            scan(target, w + " in " + path + ", line " + std::to_string(t[k].line), depth + 1);
        if (!why.empty()) return why;
      }
    }
    return "";
  }

private:
  std::string top_;
  std::set<std::string> visited_;
};

} // namespace

std::string checkGeoProgram(const std::string &path)
{
  return GeoScanner(path).scan(path, "", 0);
}

} // namespace poroseam
