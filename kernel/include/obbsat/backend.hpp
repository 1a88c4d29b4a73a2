// Backends: the instruction sets a batch kernel is compiled for, and the
// run-time choice among them.
//
// Every backend gives verdicts bitwise identical to the scalar reference of the
// same method; they differ only in speed. `automatic` picks, in this order, the
// environment variable OBBSAT_BACKEND (read once per process) or else the best
// backend this CPU runs: avx512, avx2, sse2, scalar.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace obbsat {

enum class backend {
    automatic,  ///< OBBSAT_BACKEND if set, else the best this CPU runs
    scalar,     ///< the scalar reference, one pair at a time; runs everywhere
    sse2,       ///< 4 pairs per vector
    avx2,       ///< 8 pairs per vector
    avx512,     ///< 16 pairs per vector (AVX-512 F, CD, DQ, BW)
};

/// The lower-case name of a backend, as the CLI and OBBSAT_BACKEND spell it.
const char* backend_name(backend b);

/// The backend called `name` ("auto" is automatic), or nothing if there is none.
std::optional<backend> parse_backend(std::string_view name);

/// The backends compiled into this build, best first; scalar is always last.
std::vector<backend> compiled_backends();

/// True iff `b` is compiled in and this CPU (and its OS) can run it.
bool cpu_supports(backend b);

/// The compiled backends this CPU runs, best first; scalar is always last.
std::vector<backend> runnable_backends();

/// The best backend this CPU runs, ignoring OBBSAT_BACKEND.
backend best_supported_backend();

/// The backend OBBSAT_BACKEND names (automatic for "auto"), or nothing when it
/// is unset or empty; throws unsupported_backend when it names no backend.
std::optional<backend> forced_backend();

/// The concrete backend a request resolves to; throws unsupported_backend when
/// the request (or OBBSAT_BACKEND) names one that is unknown or cannot run here.
backend resolve_backend(backend requested);

/// Lanes (pairs decided per vector) of a backend: 1, 4, 8 or 16.
unsigned backend_lanes(backend b);

}  // namespace obbsat
