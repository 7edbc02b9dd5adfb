// Whole-file writes that a reader never sees half done. Internal to src/output.
#pragma once

#include <string>

namespace poroseam {

/// This process alone: writes `text` to `path` + ".tmp", then renames it to `path`, so that
/// `path` holds either its old or its new text, also when the disk fills up (the temporary is
/// removed then). Never through a symbolic link (O_NOFOLLOW): a link's target is not ours to
/// write; the rename replaces a link at `path` itself. Returns false with the reason in *why.
bool replaceFileContents(const std::string &path, const std::string &text, std::string *why);

} // namespace poroseam
