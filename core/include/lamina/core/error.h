// The error types every command reports as one clear line on stderr (exit code 1).
#pragma once

#include <stdexcept>
#include <string>

namespace lamina {

/// A problem with what the user gave us: a file, a parameter, a scene. The message names
/// the file, the JSON path or line, and what was expected.
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace lamina
