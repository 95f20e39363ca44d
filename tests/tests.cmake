# SPDX-License-Identifier: BSD-3-Clause
# Labels: `quick` for the tests that together run in under a minute on an
# idle machine (tools/test.sh --quick, the developer's loop), `slow` for the
# rest; CI and tools/test.sh run both.
set(BG_SLOW_TESTS valgrind_outputs fuzz_short render_examples render api index_agree export_cli
    report_cli threads install equations_json sim_iteration sim_accuracy verify_bound
    symbols_rule figures scale fonts contrib components fmu_cli transform_cli linear_cli
    plot_cli mutated_models sim_bridge sim_time_events include_rule deb html_browser html_report
    large_memory gallery export_keywords export_parts export_events property_found)
# The tests' Python: the package's interpreter (Python3_EXECUTABLE, chosen in
# CMakeLists.txt: Debian's /usr/bin/python3 by default), put first on every
# test's PATH as build/tests/bin/python3. The scripts call `python3`
# hundreds of times; a version manager's shim found first on PATH (pyenv's
# costs 0.4 s a call) doubled property_found's time and lacks NumPy and SciPy.
find_package(Python3 COMPONENTS Interpreter REQUIRED)
set(BG_TEST_PYTHON ${Python3_EXECUTABLE})
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/tests/bin)
file(CREATE_LINK ${BG_TEST_PYTHON} ${CMAKE_BINARY_DIR}/tests/bin/python3 SYMBOLIC)

function(bg_label name)
  if(name IN_LIST BG_SLOW_TESTS)
    set_property(TEST ${name} APPEND PROPERTY LABELS slow)
  else()
    set_property(TEST ${name} APPEND PROPERTY LABELS quick)
  endif()
endfunction()

# Every tests/unit/test_<name>.c is one test executable linked with the engine
# (and the renderers when they exist).
function(bg_add_test name)
  add_executable(test_${name} ${CMAKE_SOURCE_DIR}/tests/unit/test_${name}.c)
  target_include_directories(test_${name} PRIVATE ${CMAKE_SOURCE_DIR}/tests/unit)
  target_link_libraries(test_${name} PRIVATE ${BG_LIBS})
  # a test that drives SUNDIALS itself (an independent solution) links it; the
  # engine opens it on first use (src/simulate/simulate_sundials_int.h)
  file(STRINGS ${CMAKE_SOURCE_DIR}/tests/unit/test_${name}.c sun REGEX "^#include <(cvode|ida|nvector|sun)")
  if(sun)
    target_link_libraries(test_${name} PRIVATE ${BG_SUNDIALS_LIBS})
  endif()
  target_compile_definitions(test_${name} PRIVATE
    BG_SOURCE_DIR="${CMAKE_SOURCE_DIR}" BG_BINARY_DIR="${CMAKE_BINARY_DIR}"
    BG_EXE="$<TARGET_FILE:bgdraw>")
  add_test(NAME ${name} COMMAND test_${name})
  set_tests_properties(${name} PROPERTIES TIMEOUT 600
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  bg_label(${name})
endfunction()

file(GLOB BG_UNIT_TESTS CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/unit/test_*.c)
# test_api is a program of libbgdraw's users: the public header and the
# shared library only, nothing of the engine.
list(REMOVE_ITEM BG_UNIT_TESTS ${CMAKE_SOURCE_DIR}/tests/unit/test_api.c)
add_executable(test_api ${CMAKE_SOURCE_DIR}/tests/unit/test_api.c)
target_include_directories(test_api PRIVATE ${CMAKE_SOURCE_DIR}/tests/unit)
target_link_libraries(test_api PRIVATE libbgdraw m)
target_compile_definitions(test_api PRIVATE BG_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
  BG_BINARY_DIR="${CMAKE_BINARY_DIR}" BG_EXE="$<TARGET_FILE:bgdraw>")
add_test(NAME api COMMAND test_api)
set_tests_properties(api PROPERTIES TIMEOUT 900 WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
bg_label(api)
foreach(f ${BG_UNIT_TESTS})
  get_filename_component(n ${f} NAME_WE)
  string(REGEX REPLACE "^test_" "" n ${n})
  bg_add_test(${n})
endforeach()

# test_simalloc counts the engine's allocations through the linker's --wrap.
if(TARGET test_simalloc)
  target_link_options(test_simalloc PRIVATE
    -Wl,--wrap=malloc -Wl,--wrap=calloc -Wl,--wrap=realloc)
endif()

# Script-driven tests (shell), one per tests/*.sh
file(GLOB BG_SCRIPT_TESTS CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/*.sh)
foreach(f ${BG_SCRIPT_TESTS})
  get_filename_component(n ${f} NAME_WE)
  add_test(NAME ${n} COMMAND bash ${f} $<TARGET_FILE:bgdraw>)
  set_tests_properties(${n} PROPERTIES TIMEOUT 900 WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  bg_label(${n})
endforeach()
include(${CMAKE_SOURCE_DIR}/tests/fuzz/fuzz.cmake)

# The property campaign (docs/property.md): a short deterministic run of
# generated models against the physics and each other, and the shrinker's
# self-test.
add_executable(prop_libjson ${CMAKE_SOURCE_DIR}/tests/property/libjson.c)
target_link_libraries(prop_libjson PRIVATE libbgdraw)
add_test(NAME property_short COMMAND bash ${CMAKE_SOURCE_DIR}/tests/property/short.sh
         $<TARGET_FILE:bgdraw> $<TARGET_FILE:prop_libjson>)
add_test(NAME property_shrink COMMAND ${BG_TEST_PYTHON} ${CMAKE_SOURCE_DIR}/tests/property/prop.py --self-test)
add_test(NAME property_found COMMAND bash ${CMAKE_SOURCE_DIR}/tests/property/found.sh $<TARGET_FILE:bgdraw>)
set_tests_properties(property_short property_shrink property_found PROPERTIES TIMEOUT 900
                     WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_property(TEST property_short APPEND PROPERTY LABELS slow)
bg_label(property_shrink)
bg_label(property_found)

# test_threads drives runs through the outputs table (src/output), which the
# executable and libbgdraw compile in; the test links the renderers directly.
if(TARGET test_threads)
  target_sources(test_threads PRIVATE ${BG_OUTPUT_SRC})
endif()
