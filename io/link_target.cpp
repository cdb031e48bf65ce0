#include "io/link_target.hpp"

#include <stdexcept>
#include <system_error>

namespace covsim {

namespace fs = std::filesystem;

fs::path link_target(fs::path p) {
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
    const fs::path text = fs::read_symlink(p, ec);
    if (ec) throw std::runtime_error(p.string() + ": cannot read the link: " + ec.message());
    p = text.is_absolute() ? text : p.parent_path() / text;
  }
  throw std::runtime_error(p.string() + ": too many levels of symbolic links");
}

}  // namespace covsim
