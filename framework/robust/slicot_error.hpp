#pragma once
// LAPACK and SLICOT report a bad argument by calling XERBLA, whose default
// prints and stops the process. Ours records the routine and the argument
// instead and returns, so the routine returns with INFO < 0 and the caller
// turns it into a message (never an exit from inside a library).
#include <string>

namespace hystbench::robust {

// "SB10AD: argument 7 is invalid" after a call that ended with INFO < 0
// (the last XERBLA report of this thread), then cleared.
std::string take_argument_error(const std::string& routine, int info);

}  // namespace hystbench::robust
