#pragma once
// Random maps that make local planners work, for the planner contract suite: a rectangular
// room (sometimes with rectangular notches cut into its walls, so that points in a notch lie
// outside the outer boundary) holding obstacles of the shapes that trap Bug algorithms:
// thin walls, T-walls, L-, E-, comb-shaped walls, cups (U-shapes) and boxes, each at an
// arbitrary angle and size, kept `clearance` apart from each other and from the walls. The
// same seed gives the same map on any machine.
#include <cstdint>
#include <string_view>
#include <vector>

#include "geometry/environment.hpp"

namespace covsim {

enum class ObstacleShape { box, thin_wall, t_wall, l_wall, e_wall, comb, cup };
std::string_view to_string(ObstacleShape s);

struct ObstacleCourseSpec {
  double width = 10.0, height = 8.0;  // metres
  std::uint32_t obstacles = 7;        // at most; fewer when they do not fit
  double clearance = 0.15;            // between obstacles and from the walls, metres
  std::uint32_t notches = 2;          // at most, cut into the bottom and top walls
};

struct ObstacleCourse {
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> holes;
  std::vector<ObstacleShape> shapes;  // of each hole
  // The narrowest passage anywhere: the clearance, a notch, or a slot between the arms of an
  // E, a comb or a cup, which may be narrower than the clearance.
  double narrowest = 0.0;
};

// Throws std::invalid_argument for a spec out of range.
ObstacleCourse obstacle_course(std::uint64_t seed, const ObstacleCourseSpec& spec = {});

// A room holding one comb between a robot and its goal: a bar with 5 to 9 teeth 1 to 1.5 m
// deep pointing at the robot's side, gaps of 0.3 to 0.6 m between them (dead ends a Bug
// algorithm that follows by touch walks into one after another). Starts lie in `below`,
// 0.2 to 1.2 m short of the teeth's tips; goals in `above`, 0.2 to 1.2 m behind the bar.
struct CombCourse {
  ObstacleCourse course;  // one hole, the comb
  Box below, above;
  double depth = 0.0;  // of the teeth
};
CombCourse comb_course(std::uint64_t seed);

}  // namespace covsim
