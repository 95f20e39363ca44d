# SPDX-License-Identifier: BSD-3-Clause
"""Where `cmake --install` puts the bgdraw package for this interpreter:
    python3 sitedir.py PREFIX
prints the folder of pure-Python packages under PREFIX that the interpreter
reads (python.cmake runs it at install time, so --prefix counts):
- Debian's system folder for PREFIX /usr (/usr/lib/python3/dist-packages,
  a package's place);
- the interpreter's own default site folder when it lies under PREFIX
  (Debian's python3 with /usr/local: /usr/local/lib/python3.X/dist-packages,
  on its sys.path already);
- else PREFIX/lib/python3.X/site-packages (then put it on PYTHONPATH)."""
import os
import sys
import sysconfig


def site_dir(prefix):
    prefix = os.path.abspath(prefix)
    if prefix == "/usr" and "deb_system" in sysconfig.get_scheme_names():
        return sysconfig.get_path("purelib", "deb_system")
    default = sysconfig.get_path("purelib")
    if default and os.path.commonpath([prefix, os.path.abspath(default)]) == prefix:
        return default
    return sysconfig.get_path("purelib", "posix_prefix", vars={"base": prefix, "platbase": prefix})


if __name__ == "__main__":
    print(site_dir(sys.argv[1]))
