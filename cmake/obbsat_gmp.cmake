# GMP with its C++ interface (gmpxx.h, libgmp, libgmpxx; Debian: libgmp-dev),
# needed only by the tests that check against exact rationals (in tests/oracle
# and tests/exact). The library, the program and every other test build
# without it.
#
# OBBSAT_TESTS_WITH_GMP (default ON) builds those tests when GMP is found; when
# it is not, configuring still succeeds and says which tests are left out. Set
# it OFF to leave them out on purpose. When they are built, the target
# obbsat_test_gmp carries GMP's include directory and libraries.
option(OBBSAT_TESTS_WITH_GMP "Build the tests that check against GMP rationals, if GMP is found" ON)
if(NOT OBBSAT_TESTS_WITH_GMP)
  message(STATUS "tests against GMP rationals left out: OBBSAT_TESTS_WITH_GMP is OFF")
  return()
endif()

find_path(OBBSAT_GMPXX_INCLUDE gmpxx.h)
find_library(OBBSAT_GMP_LIBRARY gmp)
find_library(OBBSAT_GMPXX_LIBRARY gmpxx)
# A path given by hand that holds no GMP counts as not found too.
if(NOT EXISTS "${OBBSAT_GMPXX_INCLUDE}/gmpxx.h" OR NOT EXISTS "${OBBSAT_GMP_LIBRARY}"
   OR NOT EXISTS "${OBBSAT_GMPXX_LIBRARY}")
  message(WARNING "GMP with its C++ interface not found (gmpxx.h: ${OBBSAT_GMPXX_INCLUDE}, "
                  "libgmp: ${OBBSAT_GMP_LIBRARY}, libgmpxx: ${OBBSAT_GMPXX_LIBRARY}): the tests "
                  "against GMP rationals are left out. Install it (Debian: libgmp-dev) to build "
                  "them, or set OBBSAT_TESTS_WITH_GMP=OFF to leave them out without this warning.")
  return()
endif()

add_library(obbsat_test_gmp INTERFACE)
target_include_directories(obbsat_test_gmp INTERFACE ${OBBSAT_GMPXX_INCLUDE})
target_link_libraries(obbsat_test_gmp INTERFACE ${OBBSAT_GMPXX_LIBRARY} ${OBBSAT_GMP_LIBRARY})
