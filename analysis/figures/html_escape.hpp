#pragma once
// Text safe inside HTML elements and attribute values (&, <, > and " as entities), for the
// pages covsim writes (replay.html, a sweep's index.html).
#include <string>

namespace covsim {

std::string html_escape(const std::string& s);

}  // namespace covsim
