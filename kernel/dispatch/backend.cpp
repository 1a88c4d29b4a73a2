// The dispatcher: the table of backends in priority order, ending at the
// scalar path, and the choice among them. Compiled at the baseline ISA.
#include "dispatch/backend_catalogue.hpp"
#include "dispatch/backend_registry.hpp"
#include "dispatch/compiled_kernels.hpp"
#include "dispatch/cpu_features.hpp"

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

// A SIMD row whose kernels this build left out (compiled_kernels.hpp) stays in
// the registry (its name parses) but never resolves.
template <class Row>
constexpr backend_entry entry_of(Row) {
    if constexpr (!detail::kernels_compiled<Row>()) {
        return backend_entry{Row::id, Row::name, Row::lanes, false, [] { return false; }, nullptr};
    } else {
        return backend_entry{Row::id, Row::name, Row::lanes, true, Row::runs_here, detail::kernels_of<Row>};
    }
}

// Best first; the scalar path is last and runs everywhere.
constexpr auto registry = detail::backend_catalogue::map([](auto row) { return entry_of(row); });

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
        // "auto, scalar, sse2, avx2 or avx512": the registry from its end.
        std::string expected = "auto";
        for (std::size_t k = registry.size(); k-- > 0;) {
            expected += std::string(k == 0 ? " or " : ", ") + registry[k].name;
        }
        throw unsupported_backend(std::string("OBBSAT_BACKEND=") + value + " names no backend (expected " +
                                  expected + ")");
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

std::vector<backend> runnable_backends() {
    std::vector<backend> out;
    for (const backend b : compiled_backends()) {
        if (cpu_supports(b)) {
            out.push_back(b);
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
    // A garbage OBBSAT_BACKEND is an error at every entry point, also when
    // the caller names a backend (which then wins over a valid variable).
    (void)forced_backend();
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
    return e != nullptr && e->compiled ? e->table() : kernels_of<scalar_backend>();
}

}  // namespace detail

}  // namespace obbsat
