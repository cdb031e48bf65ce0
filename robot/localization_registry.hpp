#pragma once
// The registry of localizations: a scenario's "robots": {"localization": {"type": NAME, ...}}.
#include "robot/localization.hpp"

namespace covsim {

Registry<LocalizationEntry>& localization_registry();

// The localization a configuration names (null for `exact`); unknown types throw
// std::invalid_argument naming the registered ones.
std::unique_ptr<Localization> make_localization(const LocalizationConfig& config,
                                                const LocalizationContext& context);

}  // namespace covsim
