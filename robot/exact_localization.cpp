#include "robot/exact_localization.hpp"

namespace covsim {

LocalizationEntry exact_localization_entry() {
  LocalizationEntry e;
  e.name = "exact";
  e.description = "every robot knows its position (the paper's simulations)";
  e.make = [](const LocalizationContext&, const Params&) {
    return std::unique_ptr<Localization>();
  };
  return e;
}

}  // namespace covsim
