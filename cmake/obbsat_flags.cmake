# Compiler flags shared by every obbsat target.
#
# -ffp-contract=off: GCC would otherwise fuse a*b+c into one FMA wherever the
# target ISA has it (the AVX2 and AVX-512 kernels) but not in the baseline
# scalar reference, and the verdicts would stop being bitwise identical.
# Every method states its exact IEEE operation order; fusing is never implicit.
# -ffast-math is never used: it reorders arithmetic and flushes subnormals.
set(OBBSAT_FP_FLAGS -ffp-contract=off -fno-fast-math)

function(obbsat_strict_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wconversion -Wsign-conversion -Wshadow -Wpedantic)
endfunction()

function(obbsat_target_defaults target)
  target_compile_options(${target} PRIVATE ${OBBSAT_FP_FLAGS})
  obbsat_strict_warnings(${target})
endfunction()
