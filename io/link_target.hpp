#pragma once
// Where a chain of symbolic links ends: an output named through a link is written where the
// link points, and the link stays (covsim never replaces a file it did not write).
#include <filesystem>

namespace covsim {

// The path itself if it is not a link; each link's text is taken relative to its own folder.
// The end may not exist yet (a dangling link). Throws std::runtime_error on a link that
// cannot be read or a loop (more than 40 links).
std::filesystem::path link_target(std::filesystem::path p);

}  // namespace covsim
