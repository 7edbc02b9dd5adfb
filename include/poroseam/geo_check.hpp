// A Gmsh .geo file is a program, not data: its commands can run any shell command
// (SystemCall), start a ONELAB client (OnelabRun) or write files anywhere (Save, Print,
// CreateDir, Printf > "file"). Before gmsh runs one, poroseam reads it (and every file it
// Includes or Merges) and refuses those commands, in one line naming the file and the line.
#pragma once

#include <string>

namespace poroseam {

/// Scans the .geo at `path` (and, recursively, every file it names in Include, Merge or
/// ShapeFromFile with a literal string) outside comments and strings for commands that run a
/// program or write a file. Returns "" when none is found, else one line naming the file,
/// its line and the command. An Include/Merge whose file name is not one literal string
/// (StrCat, a variable: unknown before gmsh runs) is refused too, as is a missing file.
std::string checkGeoProgram(const std::string &path);

} // namespace poroseam
