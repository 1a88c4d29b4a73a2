// Whether this test binary runs under AddressSanitizer (CI's sanitizer suite).
// The sanitizers look for memory errors and undefined behaviour, which every
// path meets in its first chunk of pairs; the volume tests that prove rare
// verdicts equal run their full size in the release suite and a smaller share
// under the sanitizers, where each pair costs some ten times more.
#pragma once

#include <cstddef>

namespace obbsat::test_support {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool under_sanitizers = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool under_sanitizers = true;
#else
constexpr bool under_sanitizers = false;
#endif
#else
constexpr bool under_sanitizers = false;
#endif

/// `full` in the release suite, `sanitized` under the sanitizers.
constexpr std::size_t volume(std::size_t full, std::size_t sanitized) {
    return under_sanitizers ? sanitized : full;
}

}  // namespace obbsat::test_support
