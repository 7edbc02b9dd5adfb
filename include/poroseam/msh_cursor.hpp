// A cursor over the bytes of a Gmsh .msh file for msh_check.cpp: tokens and lines for the
// ASCII parts, raw values for the binary ones, and where it is for messages.
#pragma once

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace poroseam::msh {

/// A cursor over the file's bytes: tokens and lines for ASCII parts, raw values for binary.
class Cursor {
public:
  explicit Cursor(const std::string &data) : d_(data) {}

  bool atEnd() const { return pos_ >= d_.size(); }
  size_t pos() const { return pos_; }

  /// Where the cursor is, for messages: "line N" (ASCII) or "byte N" (binary data).
  std::string where(bool binary) const
  {
    if (binary) return "byte " + std::to_string(pos_);
    long line = 1;
    for (size_t i = 0; i < pos_ && i < d_.size(); ++i)
      line += d_[i] == '\n';
    return "line " + std::to_string(line);
  }

  void skipSpace()
  {
    while (pos_ < d_.size() && std::isspace((unsigned char)d_[pos_]))
      ++pos_;
  }

  /// The next whitespace-separated token; "" at the end of the file.
  std::string token()
  {
    skipSpace();
    const size_t start = pos_;
    while (pos_ < d_.size() && !std::isspace((unsigned char)d_[pos_]))
      ++pos_;
    return d_.substr(start, pos_ - start);
  }

  /// The rest of the current line (without '\r'), moving past its '\n'.
  std::string line()
  {
    const size_t start = pos_;
    while (pos_ < d_.size() && d_[pos_] != '\n')
      ++pos_;
    std::string s = d_.substr(start, pos_ - start);
    if (pos_ < d_.size()) ++pos_;
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t'))
      s.pop_back();
    return s;
  }

  bool integer(long long *v)
  {
    const std::string t = token();
    if (t.empty()) return false;
    errno = 0;
    char *end = nullptr;
    *v = std::strtoll(t.c_str(), &end, 10);
    return errno == 0 && end && *end == '\0';
  }

  bool real(double *v)
  {
    const std::string t = token();
    if (t.empty()) return false;
    char *end = nullptr;
    *v = std::strtod(t.c_str(), &end);
    return end && *end == '\0';
  }

  bool raw(void *out, size_t n)
  {
    if (d_.size() - pos_ < n || pos_ > d_.size()) return false;
    std::memcpy(out, d_.data() + pos_, n);
    pos_ += n;
    return true;
  }

  /// Moves just past the next occurrence of `marker` at the start of a line; false if none.
  bool skipPast(const std::string &marker)
  {
    size_t at = pos_;
    while (true) {
      at = d_.find(marker, at);
      if (at == std::string::npos) return false;
      if (at == 0 || d_[at - 1] == '\n') break;
      at += marker.size();
    }
    pos_ = at + marker.size();
    return true;
  }

private:
  const std::string &d_;
  size_t pos_ = 0;
};

} // namespace poroseam::msh
