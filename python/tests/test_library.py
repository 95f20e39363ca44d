# SPDX-License-Identifier: BSD-3-Clause
"""The package and its library: every record declared in bgdraw/_lib.py has
the layout the C compiler gives include/bgdraw.h, the package's version is the
library's, and a missing or mismatched library is refused with a message that
says what to do."""
import ctypes
import os
import subprocess
import sys

import bgdraw
from bgdraw import _lib
from conftest import BUILD, ROOT


def test_records_have_the_headers_layout(tmp_path):
    lines = ["#include <bgdraw.h>", "#include <stddef.h>", "#include <stdio.h>", "int main(void) {"]
    for cname, record in _lib.RECORDS.items():
        lines.append(f'  printf("{cname} sizeof %zu\\n", sizeof({cname}));')
        for field, _ in record._fields_:
            c = field.rstrip("_")  # from_ is C's from
            lines.append(f'  printf("{cname} {field} %zu\\n", offsetof({cname}, {c}));')
    lines += ["  return 0;", "}"]
    (tmp_path / "layout.c").write_text("\n".join(lines) + "\n")
    subprocess.run(["cc", "-std=c11", "-Wall", "-Werror", f"-I{ROOT}/include", f"-I{BUILD}/include",
                    "-o", str(tmp_path / "layout"), str(tmp_path / "layout.c")], check=True)
    out = subprocess.run([str(tmp_path / "layout")], capture_output=True, text=True, check=True).stdout
    want = {}
    for cname, record in _lib.RECORDS.items():
        want[(cname, "sizeof")] = ctypes.sizeof(record)
        for field, _ in record._fields_:
            want[(cname, field)] = getattr(record, field).offset
    got = {(a, b): int(n) for a, b, n in (line.split() for line in out.splitlines())}
    assert got == want
    assert len(got) > 80  # every field of the eleven records


def test_version_is_the_librarys():
    v = open(os.path.join(BUILD, "include", "bgdraw_version.h")).read()
    assert f'#define BGDRAW_VERSION_STRING "{bgdraw.__version__}"' in v
    assert f"#define BGDRAW_API_VERSION {bgdraw.API_VERSION}\n" in v
    assert os.path.samefile(bgdraw.library, os.path.join(BUILD, "libbgdraw.so.0"))


def _import_with(library):
    env = dict(os.environ, BGDRAW_LIBRARY=library)
    return subprocess.run([sys.executable, "-c", "import bgdraw"], env=env, capture_output=True,
                          text=True)


def test_a_mismatched_library_is_refused(tmp_path):
    (tmp_path / "old.c").write_text('const char *bgd_version(void) { return "0.1.0"; }\n'
                                    "int bgd_api_version(void) { return 1; }\n")
    subprocess.run(["cc", "-shared", "-fPIC", "-o", str(tmp_path / "libold.so"),
                    str(tmp_path / "old.c")], check=True)
    p = _import_with(str(tmp_path / "libold.so"))
    assert p.returncode != 0
    last = p.stderr.strip().splitlines()[-1]
    assert last.startswith("bgdraw._lib.LibraryError: bgdraw: the Python package "
                           f"{bgdraw.__version__} (library API {bgdraw.API_VERSION}) cannot use "
                           "libbgdraw 0.1.0 (API 1) at ")
    assert "cmake --install" in last


def test_a_missing_library_is_refused(tmp_path):
    p = _import_with(str(tmp_path / "libnothere.so"))
    assert p.returncode != 0 and "cannot load libbgdraw" in p.stderr
    (tmp_path / "other.c").write_text("int something(void) { return 0; }\n")
    subprocess.run(["cc", "-shared", "-fPIC", "-o", str(tmp_path / "libother.so"),
                    str(tmp_path / "other.c")], check=True)
    p = _import_with(str(tmp_path / "libother.so"))
    assert p.returncode != 0 and "is not libbgdraw" in p.stderr
