# obbsat_add_isa_kernel(<target> <backend> <flags>...)
#
# Compiles kernel/lanes/backend_isa.cpp once more as an object library for one
# instruction set: the same kernel source, instantiated for the xsimd
# architecture that kernel/dispatch/backend_catalogue.hpp gives <backend>, and compiled
# with that ISA's flags only. Nothing in such an object may run before
# the dispatcher (compiled at the baseline ISA) has checked the CPU.
function(obbsat_add_isa_kernel target backend)
  set(flags ${ARGN})
  add_library(${target} OBJECT ${PROJECT_SOURCE_DIR}/kernel/lanes/backend_isa.cpp)
  target_compile_definitions(${target} PRIVATE OBBSAT_ISA_NAME=${backend})
  target_compile_options(${target} PRIVATE ${flags})
  target_link_libraries(${target} PRIVATE obbsat_ref obbsat_oracle)
  target_include_directories(${target} SYSTEM PRIVATE ${OBBSAT_XSIMD_INCLUDE_DIRS})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/kernel
                                               ${PROJECT_SOURCE_DIR}/kernel/include)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  obbsat_target_defaults(${target})
endfunction()
