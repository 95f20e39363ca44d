# SPDX-License-Identifier: BSD-3-Clause
# Fuzz targets (tests/fuzz/README.md). Every build makes fuzz_<target> with
# the deterministic driver (driver.c), which tests/fuzz_short.sh runs; with
# clang and -DBG_LIBFUZZER=ON (tests/fuzz/campaign.sh) they link libFuzzer
# instead, for long coverage-guided campaigns.
option(BG_LIBFUZZER "link the fuzz targets with clang's libFuzzer" OFF)
file(GLOB BG_FUZZ_TARGETS CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/fuzz/fuzz_*.c)
foreach(f ${BG_FUZZ_TARGETS})
  get_filename_component(n ${f} NAME_WE)
  if(BG_LIBFUZZER)
    add_executable(${n} ${f})
    target_link_options(${n} PRIVATE -fsanitize=fuzzer)
  else()
    add_executable(${n} ${f} ${CMAKE_SOURCE_DIR}/tests/fuzz/driver.c)
  endif()
  target_link_libraries(${n} PRIVATE ${BG_LIBS})
  target_compile_definitions(${n} PRIVATE BG_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
endforeach()
