#pragma once
// Errors that reach the user. An InputError is the user's to fix (bad file,
// bad key, bad value): the command line turns it into one message and exit
// code 2. Its text always names where the problem is (file and line, or the
// JSON key) and what would be valid.
#include <stdexcept>
#include <string>

namespace hystbench {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A named input file that does not exist. Its own type, so that a caller
// that knows which script makes the file can say so.
class MissingFileError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace hystbench
