# SPDX-License-Identifier: BSD-3-Clause
# Installs the bgdraw package (python.cmake runs this at `cmake --install`
# time, so CMAKE_INSTALL_PREFIX is the --prefix given then). Set by the
# caller: BG_PY_PYTHON, BG_PY_SOURCE (python/), BG_PY_BINARY (a scratch
# folder), BG_PY_LIBDIR (LIBDIR, relative or absolute), BG_PY_LIBFILE
# (libbgdraw.so.N), BG_PY_SITEDIR (empty: python/sitedir.py decides),
# PROJECT_VERSION, PROJECT_VERSION_MAJOR, BG_API_VERSION.
if(BG_PY_SITEDIR)
  set(site ${BG_PY_SITEDIR})
  if(NOT IS_ABSOLUTE ${site})
    set(site ${CMAKE_INSTALL_PREFIX}/${site})
  endif()
else()
  execute_process(COMMAND ${BG_PY_PYTHON} ${BG_PY_SOURCE}/sitedir.py ${CMAKE_INSTALL_PREFIX}
                  OUTPUT_VARIABLE site OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT site)
    message(FATAL_ERROR "bgdraw: ${BG_PY_PYTHON} could not name its site folder (${rc})")
  endif()
endif()
set(libdir ${BG_PY_LIBDIR})
if(NOT IS_ABSOLUTE ${libdir})
  set(libdir ${CMAKE_INSTALL_PREFIX}/${libdir})
endif()
# the library relative to the package: a moved prefix keeps working
file(RELATIVE_PATH BG_PY_LIBRARY ${site}/bgdraw ${libdir}/${BG_PY_LIBFILE})
configure_file(${BG_PY_SOURCE}/bgdraw/_config.py.in ${BG_PY_BINARY}/install/_config.py @ONLY)
file(GLOB sources ${BG_PY_SOURCE}/bgdraw/*.py)
file(INSTALL ${sources} ${BG_PY_BINARY}/install/_config.py DESTINATION ${site}/bgdraw)
