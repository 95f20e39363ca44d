# SPDX-License-Identifier: BSD-3-Clause
# The Python package bgdraw (docs/python.md): a copy in the build tree,
# build/python/bgdraw, that imports with PYTHONPATH=build/python and loads
# build/libbgdraw.so; `cmake --install` puts it into the interpreter's site
# folder (python/sitedir.py) beside a _config.py that finds the installed
# library (install component python3-bgdraw, Debian's name for such a
# package; tools/packaging.cmake packages the components it lists). The
# interpreter: Python3_EXECUTABLE, chosen in CMakeLists.txt (Debian's
# /usr/bin/python3 by default, whose python3-numpy, python3-pytest and
# Jupyter packages the package and its tests use).
option(BG_PYTHON "Build and install the Python package" ON)
set(BG_PYTHON_SITEDIR "" CACHE STRING
    "Where to install the Python package (relative: to the prefix); empty: the interpreter's site folder")
if(BG_PYTHON)
  find_package(Python3 COMPONENTS Interpreter)
  if(NOT Python3_Interpreter_FOUND)
    message(STATUS "bgdraw: no Python 3 interpreter: the Python package is not built")
    set(BG_PYTHON OFF)
  endif()
endif()
if(BG_PYTHON)
  set(BG_PY_OUT ${CMAKE_BINARY_DIR}/python/bgdraw)
  file(GLOB BG_PY_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/python/bgdraw/*.py)
  foreach(f ${BG_PY_SOURCES})
    get_filename_component(n ${f} NAME)
    configure_file(${f} ${BG_PY_OUT}/${n} COPYONLY)
  endforeach()
  set(BG_PY_LIBFILE libbgdraw.so.${PROJECT_VERSION_MAJOR})
  file(RELATIVE_PATH BG_PY_LIBRARY ${BG_PY_OUT} ${CMAKE_BINARY_DIR}/${BG_PY_LIBFILE})
  configure_file(${CMAKE_SOURCE_DIR}/python/bgdraw/_config.py.in ${BG_PY_OUT}/_config.py @ONLY)
  install(CODE "
    set(BG_PY_PYTHON \"${Python3_EXECUTABLE}\")
    set(BG_PY_SOURCE \"${CMAKE_SOURCE_DIR}/python\")
    set(BG_PY_BINARY \"${CMAKE_BINARY_DIR}/python\")
    set(BG_PY_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
    set(BG_PY_LIBFILE \"${BG_PY_LIBFILE}\")
    set(BG_PY_SITEDIR \"${BG_PYTHON_SITEDIR}\")
    set(PROJECT_VERSION \"${PROJECT_VERSION}\")
    set(PROJECT_VERSION_MAJOR \"${PROJECT_VERSION_MAJOR}\")
    set(BG_API_VERSION \"${BG_API_VERSION}\")
    include(\"${CMAKE_SOURCE_DIR}/python/install.cmake\")" COMPONENT python3-bgdraw)
endif()

# The package's tests (python/tests, pytest) against the build tree's
# package and library; under -DCMAKE_BUILD_TYPE=Asan the sanitizer's runtime
# is preloaded into the interpreter (it must come first) and Python's own
# allocations are not leak-checked.
if(BG_PYTHON AND BUILD_TESTING)
  add_test(NAME python COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider
           ${CMAKE_SOURCE_DIR}/python/tests)
  set(BG_PY_TEST_ENV PYTHONPATH=${CMAKE_BINARY_DIR}/python PYTHONDONTWRITEBYTECODE=1
      BGDRAW_SOURCE_DIR=${CMAKE_SOURCE_DIR} BGDRAW_BINARY_DIR=${CMAKE_BINARY_DIR})
  if(CMAKE_BUILD_TYPE STREQUAL "Asan")
    execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libasan.so
                    OUTPUT_VARIABLE BG_ASAN_RT OUTPUT_STRIP_TRAILING_WHITESPACE)
    list(APPEND BG_PY_TEST_ENV LD_PRELOAD=${BG_ASAN_RT} ASAN_OPTIONS=detect_leaks=0)
  endif()
  set_tests_properties(python PROPERTIES ENVIRONMENT "${BG_PY_TEST_ENV}" TIMEOUT 900
                       WORKING_DIRECTORY ${CMAKE_SOURCE_DIR} LABELS slow)
endif()
