// String building without <format> (GCC 12 lacks it): strCat streams its arguments in order.
#pragma once

#include <sstream>
#include <string>

namespace ispm {

template <typename... Args> std::string strCat(const Args&... args) {
    std::ostringstream out;
    out.precision(9); // enough digits that a float survives the round trip
    (out << ... << args);
    return out.str();
}

} // namespace ispm
