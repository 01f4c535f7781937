// MOBB_ASSERT(condition): a documented precondition or an internal invariant, checked in Debug builds and
// in the sanitizer build (MOBB_ASSERTS defined by CMake; scripts/test's ASan stage runs with them on) and
// compiled out otherwise, its condition never evaluated. A failed one reports "FILE:LINE: FUNCTION:
// Assertion `CONDITION' failed" on stderr through the C library's own assert handler (core writes no
// files itself) and aborts. After Box2D's B2_ASSERT and Jolt's JPH_ASSERT: for what only a bug in mobb
// can break; bad input gets an exception with a one-line message instead.
#pragma once

#if defined(MOBB_ASSERTS)
#include <cassert>
#include <cstdlib>

#if defined(__GLIBC__)
// Declared here too: <cassert> leaves it out under NDEBUG (RelWithDebInfo, the sanitizer build).
extern "C" [[noreturn]] void __assert_fail(const char* assertion, const char* file, unsigned int line,
                                           const char* function) noexcept;
#define MOBB_ASSERT_FAILED(text) __assert_fail(text, __FILE__, static_cast<unsigned int>(__LINE__), __func__)
#else
#define MOBB_ASSERT_FAILED(text) std::abort()
#endif

#define MOBB_ASSERT(condition) ((condition) ? static_cast<void>(0) : MOBB_ASSERT_FAILED(#condition))
#else
// Unevaluated, so its names still count as used and cost nothing.
#define MOBB_ASSERT(condition) static_cast<void>(sizeof(!(condition)))
#endif
