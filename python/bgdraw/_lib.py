# SPDX-License-Identifier: BSD-3-Clause
"""libbgdraw through ctypes: the records and calls of include/bgdraw.h, the
library found and its version checked once, at import.

ctypes, not cffi: it is in the standard library, so the package needs nothing
but the interpreter and libbgdraw (any Python 3 the user runs, a venv's too,
with no compiler at install time); cffi's ABI mode would check the header no
better (it does not read the real one either), and its API mode needs a C
compiler and the Python headers wherever the package is installed. The one
risk of declaring the records by hand, a layout that drifts from the header,
is checked by python/tests/test_library.py, which compiles the header and
compares every field's offset with the ones declared here; the API version
check below refuses a library whose header changed since."""
import ctypes
import os

from . import _config


class Diagnostic(ctypes.Structure):
    pass


Diagnostic._fields_ = [
    ("file", ctypes.c_char_p),
    ("line", ctypes.c_int),
    ("column", ctypes.c_int),
    ("severity", ctypes.c_char_p),
    ("message", ctypes.c_char_p),
    ("nnotes", ctypes.c_int),
    ("notes", ctypes.POINTER(Diagnostic)),
]

LOG_FN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_int, ctypes.c_char_p)


class Options(ctypes.Structure):
    _fields_ = [
        ("causality", ctypes.c_char_p),
        ("nparams", ctypes.c_int),
        ("param_names", ctypes.POINTER(ctypes.c_char_p)),
        ("param_values", ctypes.POINTER(ctypes.c_double)),
        ("max_list", ctypes.c_int),
        ("max_errors", ctypes.c_int),
        ("verify", ctypes.c_int),
        ("style", ctypes.c_char_p),
        ("show", ctypes.c_char_p),
        ("highlight", ctypes.c_char_p),
        ("layout", ctypes.c_char_p),
        ("prefix", ctypes.c_char_p),
        ("log", LOG_FN),
        ("log_ctx", ctypes.c_void_p),
        ("verbose", ctypes.c_int),
        ("warnings", ctypes.c_char_p),
    ]


class Element(ctypes.Structure):
    _fields_ = [("name", ctypes.c_char_p), ("kind", ctypes.c_char_p), ("causality", ctypes.c_char_p)]


class Bond(ctypes.Structure):
    _fields_ = [("number", ctypes.c_int), ("from_", ctypes.c_char_p), ("to", ctypes.c_char_p),
                ("stroke", ctypes.c_char_p)]


class Path(ctypes.Structure):
    _fields_ = [("from_", ctypes.c_char_p), ("to", ctypes.c_char_p), ("kind", ctypes.c_char_p),
                ("cls", ctypes.c_int), ("order", ctypes.c_int), ("nbonds", ctypes.c_int),
                ("bonds", ctypes.POINTER(ctypes.c_int))]


class Loop(ctypes.Structure):
    _fields_ = [("nbonds", ctypes.c_int), ("bonds", ctypes.POINTER(ctypes.c_int)),
                ("gain", ctypes.c_char_p), ("gain_value", ctypes.c_double), ("cls", ctypes.c_int),
                ("kind", ctypes.c_char_p), ("order", ctypes.c_int), ("algebraic", ctypes.c_int)]


class Conflict(ctypes.Structure):
    _fields_ = [("element", ctypes.c_char_p), ("type", ctypes.c_int), ("degree", ctypes.c_int),
                ("nbonds", ctypes.c_int), ("bonds", ctypes.POINTER(ctypes.c_int))]


class Index(ctypes.Structure):
    _fields_ = [("form", ctypes.c_char_p), ("predicted", ctypes.c_int), ("reason", ctypes.c_char_p),
                ("numeric", ctypes.c_int), ("numeric_status", ctypes.c_char_p),
                ("reduced_form", ctypes.c_char_p), ("reduction", ctypes.c_char_p)]


DOUBLES = ctypes.POINTER(ctypes.c_double)
STRINGS = ctypes.POINTER(ctypes.c_char_p)


class Simulation(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int), ("message", ctypes.c_char_p), ("nrows", ctypes.c_int),
                ("ncolumns", ctypes.c_int), ("time", DOUBLES), ("names", STRINGS),
                ("solver", ctypes.c_char_p), ("partial", ctypes.c_int)]


class Linear(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int), ("message", ctypes.c_char_p), ("n", ctypes.c_int),
                ("nu", ctypes.c_int), ("ny", ctypes.c_int), ("reduced", ctypes.c_int),
                ("A", DOUBLES), ("B", DOUBLES), ("C", DOUBLES), ("D", DOUBLES),
                ("inputs", STRINGS), ("outputs", STRINGS), ("npoles", ctypes.c_int),
                ("pole_re", DOUBLES), ("pole_im", DOUBLES)]


class Transfer(ctypes.Structure):
    _fields_ = [("input", ctypes.c_int), ("output", ctypes.c_int), ("nnum", ctypes.c_int),
                ("nden", ctypes.c_int), ("num", DOUBLES), ("den", DOUBLES),
                ("dc_gain", ctypes.c_double), ("npoles", ctypes.c_int), ("nzeros", ctypes.c_int),
                ("pole_re", DOUBLES), ("pole_im", DOUBLES), ("zero_re", DOUBLES),
                ("zero_im", DOUBLES)]


# The records by their C names (the layout test reads this table).
RECORDS = {"bgd_diagnostic": Diagnostic, "bgd_options": Options, "bgd_element": Element,
           "bgd_bond": Bond, "bgd_path": Path, "bgd_loop": Loop, "bgd_conflict": Conflict,
           "bgd_index": Index, "bgd_simulation": Simulation, "bgd_linear": Linear,
           "bgd_transfer": Transfer}

OK, MODEL, USAGE, REFUSED, WRITE = 0, 1, 2, 3, 4
NO_ORDER = -1000000  # BGD_NO_ORDER: a path that closes no loop

HANDLE = ctypes.c_void_p
P = ctypes.POINTER
# name: (result, arguments)
CALLS = {
    "bgd_options_init": (None, [P(Options)]),
    "bgd_open": (HANDLE, [ctypes.c_char_p, ctypes.c_char_p, P(Options)]),
    "bgd_open_buffer": (HANDLE, [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_size_t, P(Options)]),
    "bgd_open_file": (HANDLE, [ctypes.c_char_p, P(Options)]),
    "bgd_status": (ctypes.c_int, [HANDLE]),
    "bgd_free": (None, [HANDLE]),
    "bgd_diagnostics": (ctypes.c_int, [HANDLE, P(P(Diagnostic))]),
    "bgd_diagnostics_text": (ctypes.c_void_p, [HANDLE]),
    "bgd_name": (ctypes.c_char_p, [HANDLE]),
    "bgd_count": (ctypes.c_int, [HANDLE, ctypes.c_char_p]),
    "bgd_element_at": (ctypes.c_int, [HANDLE, ctypes.c_int, P(Element)]),
    "bgd_bond_at": (ctypes.c_int, [HANDLE, ctypes.c_int, P(Bond)]),
    "bgd_causal_path_at": (ctypes.c_int, [HANDLE, ctypes.c_int, P(Path)]),
    "bgd_causal_loop_at": (ctypes.c_int, [HANDLE, ctypes.c_int, P(Loop)]),
    "bgd_topological_loop_at": (ctypes.c_int, [HANDLE, ctypes.c_int, P(Loop)]),
    "bgd_conflict_at": (ctypes.c_int, [HANDLE, ctypes.c_int, P(Conflict)]),
    "bgd_index_info": (ctypes.c_int, [HANDLE, P(Index)]),
    "bgd_eigenvalues": (ctypes.c_int, [HANDLE, P(DOUBLES), P(DOUBLES)]),
    "bgd_simulate": (ctypes.c_int, [HANDLE, P(Simulation)]),
    "bgd_column": (DOUBLES, [HANDLE, ctypes.c_int]),
    "bgd_linearise": (ctypes.c_int, [HANDLE, P(Linear)]),
    "bgd_transfer_function_at": (ctypes.c_int, [HANDLE, ctypes.c_int, P(Transfer)]),
    "bgd_output": (ctypes.c_int, [HANDLE, ctypes.c_char_p, ctypes.c_char_p,
                                  P(ctypes.c_void_p), P(ctypes.c_size_t)]),
    "bgd_write": (ctypes.c_int, [HANDLE, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p]),
    "bgd_last_error": (ctypes.c_char_p, [HANDLE]),
    "bgd_set_drawing": (ctypes.c_int, [HANDLE, P(Options)]),
    "bgd_version": (ctypes.c_char_p, []),
    "bgd_api_version": (ctypes.c_int, []),
}


class LibraryError(ImportError):
    """libbgdraw is missing, or is not the version this package was built for."""


def library_path():
    """$BGDRAW_LIBRARY, else the library the build installed beside the
    package (a path relative to this folder, so a moved prefix still works),
    else the system's loader path."""
    env = os.environ.get("BGDRAW_LIBRARY")
    if env:
        return env
    here = os.path.dirname(os.path.abspath(__file__))
    beside = os.path.normpath(os.path.join(here, _config.LIBRARY))
    return beside if os.path.exists(beside) else _config.SONAME


def _load():
    path = library_path()
    try:
        lib = ctypes.CDLL(path)
    except OSError as e:
        raise LibraryError(
            f"bgdraw: cannot load libbgdraw ({path}): {e}; install bgdraw with cmake --install, "
            f"or set BGDRAW_LIBRARY to the library's file") from None
    try:
        lib.bgd_version.restype = ctypes.c_char_p
        lib.bgd_api_version.restype = ctypes.c_int
        version = lib.bgd_version().decode()
        api = lib.bgd_api_version()
    except AttributeError:
        raise LibraryError(f"bgdraw: {path} is not libbgdraw (no bgd_version)") from None
    if version != _config.VERSION or api != _config.API_VERSION:
        raise LibraryError(
            f"bgdraw: the Python package {_config.VERSION} (library API {_config.API_VERSION}) "
            f"cannot use libbgdraw {version} (API {api}) at {path}: install the package and the "
            f"library from the same build (cmake --install), or point BGDRAW_LIBRARY at the "
            f"matching library")
    for name, (res, args) in CALLS.items():
        fn = getattr(lib, name)
        fn.restype, fn.argtypes = res, args
    lib.path = path
    return lib


lib = _load()
libc = ctypes.CDLL(None)
libc.free.argtypes, libc.free.restype = [ctypes.c_void_p], None


def take_string(ptr, size=None):
    """A malloc'd buffer of the library as bytes, freed."""
    if not ptr:
        return None
    try:
        return ctypes.string_at(ptr, size) if size is not None else ctypes.string_at(ptr)
    finally:
        libc.free(ptr)
