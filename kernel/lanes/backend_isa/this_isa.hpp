// The backend one per-ISA object is compiled for. Each source of this folder
// is compiled once per SIMD row of backend_catalogue.hpp (see
// cmake/obbsat_isa.cmake) with OBBSAT_ISA_NAME set to the backend's name and
// with that ISA's compiler flags only; every source of one backend gets the
// same flags, so what two of them both instantiate is the same code. Each
// defines the tables of one kind of kernel for that backend; everything else
// in them is private to the object (../README.md).
#pragma once

#include "dispatch/backend_catalogue.hpp"
#include "lanes/lanes.hpp"

#ifndef OBBSAT_ISA_NAME
#error "OBBSAT_ISA_NAME must name the backend of this translation unit"
#endif

#define OBBSAT_CONCAT_INNER(a, b) a##b
#define OBBSAT_CONCAT(a, b) OBBSAT_CONCAT_INNER(a, b)

namespace obbsat::detail {

using this_backend = OBBSAT_CONCAT(OBBSAT_ISA_NAME, _backend);
using isa_arch = this_backend::arch;
static_assert(lanes<isa_arch>::size == this_backend::lanes, "the catalogue's lane width is the arch's");

}  // namespace obbsat::detail
