# Compiler flags shared by every obbsat target.
#
# -ffp-contract=off: GCC would otherwise fuse a*b+c into one FMA wherever the
# target ISA has it (the AVX2 and AVX-512 kernels) but not in the baseline
# scalar reference, and the verdicts would stop being bitwise identical.
# Every method states its exact IEEE operation order; fusing is never implicit.
# -ffast-math is never used: it reorders arithmetic and flushes subnormals.
set(OBBSAT_FP_FLAGS -ffp-contract=off -fno-fast-math)

# The library is position independent (it may be linked into a shared
# object); without this, GCC assumes any exported function may be interposed
# at load time and refuses to inline the reference's small step functions.
set(OBBSAT_CODEGEN_FLAGS -fno-semantic-interposition)

# CI turns warnings into errors (the asan preset), so a new warning fails the
# build instead of scrolling by; off by default, as a newer compiler may warn
# about code that an older one accepted.
option(OBBSAT_WARNINGS_AS_ERRORS "Treat warnings in obbsat's own targets as errors" OFF)

function(obbsat_strict_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wconversion -Wsign-conversion -Wshadow -Wpedantic)
  if(OBBSAT_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

function(obbsat_target_defaults target)
  target_compile_options(${target} PRIVATE ${OBBSAT_FP_FLAGS} ${OBBSAT_CODEGEN_FLAGS})
  obbsat_strict_warnings(${target})
endfunction()
