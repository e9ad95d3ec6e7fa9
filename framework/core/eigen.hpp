#pragma once
// Eigen for every file of the project: include this, never <Eigen/...>.
//
// GCC 12 warns -Wmaybe-uninitialized inside its own AVX-512 intrinsics
// (avx512fintrin.h's deliberately undefined `__Y = __Y` operands, GCC bug
// 105593, fixed in later releases) wherever Eigen's packet code is inlined
// under -march=native: thousands of lines per build that hide real
// warnings. GCC checks the warning against the pragmas at every function the
// intrinsic is inlined through, our own among them, so it cannot be
// silenced around Eigen's headers alone: on GCC 12, a file that includes
// Eigen gives up -Wmaybe-uninitialized from here on. Other compilers, and
// files without Eigen, keep it.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <Eigen/Dense>
