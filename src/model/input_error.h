// The one exception type for bad input: its message is the single line the user sees.
#pragma once

#include <stdexcept>
#include <string>

namespace urbis {

/// Bad user input (file, tag, parameter). what() names the problem and the file.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace urbis
