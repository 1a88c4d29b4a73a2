# obbsat_add_isa_kernel(<target> <backend> <flags>...)
#
# Compiles the sources of kernel/lanes/backend_isa/ once more as an object
# library for one instruction set: the same kernel sources, instantiated for
# the xsimd architecture that kernel/dispatch/backend_catalogue.hpp gives
# <backend>, and compiled with that ISA's flags only. Nothing in such an object
# may run before the dispatcher (compiled at the baseline ISA) has checked the
# CPU. One source per kind of kernel (verdicts, double verdicts, contacts):
# each takes minutes under the sanitizers, and separate sources compile side
# by side.
function(obbsat_add_isa_kernel target backend)
  set(flags ${ARGN})
  set(sources_dir ${PROJECT_SOURCE_DIR}/kernel/lanes/backend_isa)
  add_library(${target} OBJECT ${sources_dir}/verdict_kernels.cpp ${sources_dir}/double_kernels.cpp
                               ${sources_dir}/contact_kernels.cpp)
  target_compile_definitions(${target} PRIVATE OBBSAT_ISA_NAME=${backend})
  target_compile_options(${target} PRIVATE ${flags})
  target_link_libraries(${target} PRIVATE obbsat_ref obbsat_oracle)
  target_include_directories(${target} SYSTEM PRIVATE ${OBBSAT_XSIMD_INCLUDE_DIRS})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/kernel
                                               ${PROJECT_SOURCE_DIR}/kernel/include)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  obbsat_target_defaults(${target})
endfunction()
