# SPDX-License-Identifier: BSD-3-Clause
# Debian packages by CPack (tools/deb.sh builds them; tests/deb.sh checks them
# with lintian). Three binary packages, as Debian splits a program with a
# library: bgdraw (the command line, its renderer module, styles, component
# library, man page, docs), libbgdraw0 (the shared library, named after its
# soname libbgdraw.so.0) and libbgdraw-dev (header, .so link, pkg-config and
# CMake files). With -DBG_DEBIAN_FILES=ON (tools/deb.sh sets it) each package
# gets the Debian copyright file and changelog, and the man page is installed
# compressed; a plain `cmake --install` stays as it was.
set(BG_DEB_PACKAGES bgdraw libbgdraw0 libbgdraw-dev)
if(BG_PYTHON)
  list(APPEND BG_DEB_PACKAGES python3-bgdraw) # python/python.cmake's install
endif()

if(BG_DEBIAN_FILES)
  find_program(BG_GZIP gzip REQUIRED)
  configure_file(${CMAKE_SOURCE_DIR}/tools/debian/changelog.in ${CMAKE_BINARY_DIR}/debian/changelog @ONLY)
  # gzip -9n: no name or time stamp in the header, so the bytes are the same each build
  add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/debian/changelog.Debian.gz
    COMMAND ${BG_GZIP} -9nc ${CMAKE_BINARY_DIR}/debian/changelog > ${CMAKE_BINARY_DIR}/debian/changelog.Debian.gz
    DEPENDS ${CMAKE_BINARY_DIR}/debian/changelog VERBATIM)
  add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/debian/bgdraw.1.gz
    COMMAND ${BG_GZIP} -9nc ${CMAKE_BINARY_DIR}/bgdraw.1 > ${CMAKE_BINARY_DIR}/debian/bgdraw.1.gz
    DEPENDS ${CMAKE_BINARY_DIR}/bgdraw.1 VERBATIM)
  add_custom_target(bg_debian_files ALL DEPENDS ${CMAKE_BINARY_DIR}/debian/changelog.Debian.gz
                    ${CMAKE_BINARY_DIR}/debian/bgdraw.1.gz)
  install(FILES ${CMAKE_BINARY_DIR}/debian/bgdraw.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
          COMPONENT bgdraw)
  foreach(p ${BG_DEB_PACKAGES})
    install(FILES ${CMAKE_SOURCE_DIR}/tools/debian/copyright ${CMAKE_BINARY_DIR}/debian/changelog.Debian.gz
            DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${p} COMPONENT ${p})
    # what lintian says that does not apply to packages built outside Debian's archive
    install(FILES ${CMAKE_SOURCE_DIR}/tools/debian/lintian-overrides DESTINATION
            ${CMAKE_INSTALL_DATADIR}/lintian/overrides RENAME ${p} COMPONENT ${p})
  endforeach()
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME bgdraw)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "the bgdraw authors")
set(CPACK_PACKAGE_CONTACT "bgdraw maintainers <maintainers@users.noreply.github.com>")
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL ${BG_DEB_PACKAGES})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)        # Depends from dpkg-shlibdeps
# libbgdraw0's shlibs file and ldconfig trigger are ours (CPack's own would call
# ldconfig from postinst and postrm, which Debian replaced by the trigger)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
file(WRITE ${CMAKE_BINARY_DIR}/debian/libbgdraw0/shlibs
     "libbgdraw ${PROJECT_VERSION_MAJOR} libbgdraw0 (>= ${PROJECT_VERSION})\n")
file(WRITE ${CMAKE_BINARY_DIR}/debian/libbgdraw0/triggers "activate-noawait ldconfig\n")
# CPack writes a postinst and postrm calling ldconfig unless the package has
# its own: these do nothing, the trigger does that work
foreach(script postinst postrm)
  file(WRITE ${CMAKE_BINARY_DIR}/debian/libbgdraw0/${script}
       "#!/bin/sh\n# ldconfig runs from the ldconfig trigger (DEBIAN/triggers)\nset -e\n"
       "case \"$1\" in\n  configure|abort-*|remove|purge|upgrade|failed-upgrade|disappear) ;;\n"
       "  *) echo \"${script} called with unknown argument '$1'\" >&2; exit 1 ;;\nesac\nexit 0\n")
endforeach()
set(CPACK_DEBIAN_LIBBGDRAW0_PACKAGE_CONTROL_EXTRA
    ${CMAKE_BINARY_DIR}/debian/libbgdraw0/shlibs ${CMAKE_BINARY_DIR}/debian/libbgdraw0/triggers
    ${CMAKE_BINARY_DIR}/debian/libbgdraw0/postinst ${CMAKE_BINARY_DIR}/debian/libbgdraw0/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE
    GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
# LAPACKE and SUNDIALS are opened on first use (src/base/lapack.h,
# src/simulate/simulate_sundials_int.h), so no ELF file names them and
# dpkg-shlibdeps cannot see them: each dependency is stated, the one the
# library's own shlibs file gives for the SONAME the build opens (the package
# name alone when the shlibs file has no line for it)
function(bg_deb_depends out lib)
  file(REAL_PATH ${lib} real)
  bg_soname(soname ${lib})
  execute_process(COMMAND dpkg-query -S ${real} OUTPUT_VARIABLE owner
                  ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  string(REGEX REPLACE ":.*" "" pkg "${owner}")
  string(REGEX REPLACE "^([^:]*):([^:]*):.*" "\\1:\\2" pkgarch "${owner}")
  # the shlibs key: "libfoo 3" for libfoo.so.3, "libfoo-1.2" for libfoo-1.2.so
  if(soname MATCHES "^(.*)\\.so\\.([0-9.]+)$")
    set(key "${CMAKE_MATCH_1} ${CMAKE_MATCH_2} ")
  else()
    string(REGEX REPLACE "\\.so$" "" key "${soname}")
    set(key "${key} ")
  endif()
  string(REPLACE "." "\\." key "${key}")
  set(dep "${pkg}")
  foreach(f /var/lib/dpkg/info/${pkgarch}.shlibs /var/lib/dpkg/info/${pkg}.shlibs)
    if(EXISTS ${f})
      file(STRINGS ${f} line REGEX "^${key}")
      if(line)
        string(REGEX MATCH "^[^ ]+ [^ ]+ (.*)$" _ "${line}")
        set(dep "${CMAKE_MATCH_1}")
        break()
      endif()
    endif()
  endforeach()
  set(${out} "${dep}" PARENT_SCOPE)
endfunction()
set(BG_STATED_DEPENDS)
foreach(lib ${LAPACKE_LIB} ${BG_SUNDIALS_LIBS})
  bg_deb_depends(dep ${lib})
  if(dep AND NOT dep IN_LIST BG_STATED_DEPENDS)
    list(APPEND BG_STATED_DEPENDS "${dep}")
  endif()
endforeach()
list(JOIN BG_STATED_DEPENDS ", " BG_STATED_DEPENDS)
set(CPACK_DEBIAN_BGDRAW_PACKAGE_DEPENDS "${BG_STATED_DEPENDS}")
set(CPACK_DEBIAN_LIBBGDRAW0_PACKAGE_DEPENDS "${BG_STATED_DEPENDS}")
set(CPACK_DEBIAN_BGDRAW_PACKAGE_NAME bgdraw)
set(CPACK_DEBIAN_BGDRAW_PACKAGE_SECTION science)
set(CPACK_DEBIAN_BGDRAW_DESCRIPTION "causal bond graphs: causality, analysis, diagrams, simulation
bgdraw reads a bond graph model written in a small text language, assigns
computational causality, finds causal paths and loops, conflicts, algebraic
loops and the DAE index, derives the equations, simulates them with SUNDIALS
and draws annotated SVG, PDF and PNG diagrams, plots and PDF reports without
a display. It exports the equations to C, Python, Octave, Modelica and FMI.")
set(CPACK_DEBIAN_LIBBGDRAW0_PACKAGE_NAME libbgdraw0)
set(CPACK_DEBIAN_LIBBGDRAW0_PACKAGE_SECTION libs)
set(CPACK_DEBIAN_LIBBGDRAW0_DESCRIPTION "causal bond graphs: analysis, diagrams and simulation (library)
libbgdraw gives programs what the bgdraw command line gives: a model's
causality and analysis as data, its equations, simulation results, linear
analysis and every output format of bgdraw, into memory or a file.
.
This package contains the shared library.")
set(CPACK_DEBIAN_LIBBGDRAW-DEV_PACKAGE_NAME libbgdraw-dev)
set(CPACK_DEBIAN_LIBBGDRAW-DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_LIBBGDRAW-DEV_PACKAGE_DEPENDS
    "libbgdraw0 (= ${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE})")
set(CPACK_DEBIAN_LIBBGDRAW-DEV_DESCRIPTION "causal bond graphs: analysis, diagrams and simulation (development files)
libbgdraw gives programs what the bgdraw command line gives: a model's
causality and analysis as data, its equations, simulation results, linear
analysis and every output format of bgdraw, into memory or a file.
.
This package contains the header, the pkg-config file and the CMake package
(find_package(bgdraw)).")
set(CPACK_DEBIAN_PYTHON3-BGDRAW_PACKAGE_NAME python3-bgdraw)
set(CPACK_DEBIAN_PYTHON3-BGDRAW_PACKAGE_SECTION python)
set(CPACK_DEBIAN_PYTHON3-BGDRAW_PACKAGE_DEPENDS
    "python3, python3-numpy, libbgdraw0 (= ${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE})")
set(CPACK_DEBIAN_PYTHON3-BGDRAW_DESCRIPTION "causal bond graphs: analysis, diagrams and simulation (Python 3)
import bgdraw: a bond graph model's causality and analysis as Python objects,
its diagram as SVG (shown inline in Jupyter, with a %%bgdraw cell magic), its
equations in LaTeX, simulation columns and state-space matrices as NumPy
arrays, and every output of the bgdraw command line, through libbgdraw.")
include(CPack)
