#pragma once
// Included before CoverageControl's sources when they are built against CGAL 5.5: CGAL 6
// returns point-location results as std::variant, CGAL 5.5 as boost::variant. The peer
// calls std::get_if on them; this overload answers for boost::variant the same way
// (a pointer to the alternative, or null), leaving the peer's sources untouched.
#include <boost/variant/get.hpp>
#include <boost/variant/variant.hpp>

namespace std {

template <class T, class... Ts>
const T* get_if(const boost::variant<Ts...>* v) noexcept {
  return boost::get<T>(v);
}

}  // namespace std
