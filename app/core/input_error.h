// User-input errors (scene files, command-line values): the message names the file, the JSON
// path and what was expected. The CLI prints it on one line and exits with code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace ispm {

class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// "file: /json/path: expected ..." with the path omitted when empty.
[[noreturn]] void throwInputError(const std::string& file, const std::string& jsonPath,
                                  const std::string& what);

} // namespace ispm
