// Whether the tests run under -fsanitize=address,undefined (QUADTRI_SANITIZE), which slows them
// five- to tenfold: the sampling tests check fewer points there.
#pragma once

namespace quadtri::test {

#ifdef QUADTRI_TEST_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace quadtri::test
