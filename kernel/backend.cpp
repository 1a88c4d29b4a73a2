// The dispatcher: the table of backends in priority order, ending at the
// scalar path, and the choice among them. Compiled at the baseline ISA.
#include "backend_registry.hpp"
#include "cpu_features.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/error.hpp>

#include <cstdlib>
#include <string>

namespace obbsat {

namespace {

struct backend_entry {
    backend id;
    const char* name;
    unsigned lanes;
    bool compiled;
    bool (*runs_here)();
    const detail::kernel_table& (*table)();
};

#if !OBBSAT_WITH_X86_KERNELS
// Never called: entries that are not compiled in are never resolved.
const detail::kernel_table& missing_table() { return detail::scalar_kernels(); }
#endif

// Best first; the scalar path is last and runs everywhere.
const backend_entry registry[] = {
#if OBBSAT_WITH_X86_KERNELS
    {backend::avx512, "avx512", 16, true, [] { return detail::this_cpu().avx512; }, detail::avx512_kernels},
    {backend::avx2, "avx2", 8, true, [] { return detail::this_cpu().avx2; }, detail::avx2_kernels},
    {backend::sse2, "sse2", 4, true, [] { return detail::this_cpu().sse2; }, detail::sse2_kernels},
#else
    {backend::avx512, "avx512", 16, false, [] { return false; }, missing_table},
    {backend::avx2, "avx2", 8, false, [] { return false; }, missing_table},
    {backend::sse2, "sse2", 4, false, [] { return false; }, missing_table},
#endif
    {backend::scalar, "scalar", 1, true, [] { return true; }, detail::scalar_kernels},
};

const backend_entry* find(backend b) {
    for (const auto& e : registry) {
        if (e.id == b) {
            return &e;
        }
    }
    return nullptr;
}

std::optional<backend> read_forced_backend() {
    const char* value = std::getenv("OBBSAT_BACKEND");
    if (value == nullptr || *value == '\0') {
        return std::nullopt;
    }
    const auto parsed = parse_backend(value);
    if (!parsed) {
        throw unsupported_backend(std::string("OBBSAT_BACKEND=") + value +
                                  " names no backend (expected auto, scalar, sse2, avx2 or avx512)");
    }
    return parsed;
}

backend from_environment_or_best() {
    const std::optional<backend> forced = forced_backend();
    if (!forced || *forced == backend::automatic) {
        return best_supported_backend();
    }
    if (!cpu_supports(*forced)) {
        throw unsupported_backend(std::string("OBBSAT_BACKEND=") + backend_name(*forced) +
                                  ": this CPU or build cannot run that backend");
    }
    return *forced;
}

}  // namespace

std::optional<backend> forced_backend() {
    // Read once: the variable is a process-wide setting, and the hot path
    // must not scan the environment on every call.
    static const std::optional<backend> forced = read_forced_backend();
    return forced;
}

const char* backend_name(backend b) {
    if (b == backend::automatic) {
        return "auto";
    }
    const backend_entry* e = find(b);
    return e ? e->name : "unknown";
}

std::optional<backend> parse_backend(std::string_view name) {
    if (name == "auto") {
        return backend::automatic;
    }
    for (const auto& e : registry) {
        if (name == e.name) {
            return e.id;
        }
    }
    return std::nullopt;
}

std::vector<backend> compiled_backends() {
    std::vector<backend> out;
    for (const auto& e : registry) {
        if (e.compiled) {
            out.push_back(e.id);
        }
    }
    return out;
}

bool cpu_supports(backend b) {
    const backend_entry* e = find(b);
    return e != nullptr && e->compiled && e->runs_here();
}

backend best_supported_backend() {
    for (const auto& e : registry) {
        if (e.compiled && e.runs_here()) {
            return e.id;
        }
    }
    return backend::scalar;
}

backend resolve_backend(backend requested) {
    if (requested == backend::automatic) {
        return from_environment_or_best();
    }
    const backend_entry* e = find(requested);
    if (e == nullptr || !e->compiled) {
        throw unsupported_backend(std::string("backend ") + backend_name(requested) +
                                  " is not compiled into this build");
    }
    if (!e->runs_here()) {
        throw unsupported_backend(std::string("backend ") + e->name +
                                  " needs instructions this CPU (or its OS) does not provide");
    }
    return requested;
}

unsigned backend_lanes(backend b) {
    const backend_entry* e = find(b);
    return e ? e->lanes : 1;
}

namespace detail {

const kernel_table& kernels_for(backend resolved) {
    const backend_entry* e = find(resolved);
    return e ? e->table() : scalar_kernels();
}

}  // namespace detail

}  // namespace obbsat
