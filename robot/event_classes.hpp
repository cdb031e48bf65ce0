#pragma once
// The priority classes of the coverage run's events: at equal times, targets first (loop 1),
// then sensing, motion (loop 2), broadcasts and deliveries, samples, and last the check.
// Components schedule their events in these classes so that same-time order never depends
// on which component scheduled first.
#include <cstdint>

#include "core/event.hpp"

namespace covsim::event_class {

constexpr Priority loop1 = 0, sense = 1, loop2 = 2, broadcast = 3, deliver = 4, sample = 5,
                   check = 6;
constexpr EntityId world = UINT32_MAX;  // the entity of events that concern every robot

}  // namespace covsim::event_class
