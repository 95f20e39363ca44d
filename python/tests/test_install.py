# SPDX-License-Identifier: BSD-3-Clause
"""`cmake --install` puts the package where the interpreter finds packages
under the prefix (python/sitedir.py), and the installed package loads the
installed library, found relative to itself: the prefix may be moved."""
import os
import shutil
import subprocess
import sys

from conftest import BUILD, ROOT, cli, example

sys.path.insert(0, os.path.join(ROOT, "python"))
from sitedir import site_dir  # noqa: E402


def test_installed_package_in_a_moved_prefix(tmp_path):
    subprocess.run(["cmake", "--install", BUILD, "--prefix", str(tmp_path / "p")], check=True,
                   capture_output=True)
    site = site_dir(str(tmp_path / "p"))
    assert site.startswith(str(tmp_path / "p") + "/")
    assert os.path.isfile(os.path.join(site, "bgdraw", "_config.py"))
    shutil.move(tmp_path / "p", tmp_path / "q")
    site = site.replace(str(tmp_path / "p"), str(tmp_path / "q"))
    shutil.copy(example("rlc.bg"), tmp_path)
    env = {k: v for k, v in os.environ.items() if k not in ("BGDRAW_LIBRARY", "BGDRAW_STYLE_DIR")}
    env["PYTHONPATH"] = site
    program = ("import bgdraw, sys\n"
               "m = bgdraw.Model.from_file('rlc.bg')\n"
               "print(bgdraw.library)\n"
               "print(round(float(m.simulate()['C1.e'][-1]), 4))\n"
               "sys.stdout.flush()\n"
               "sys.stdout.buffer.write(m.svg(style='print').encode())\n")
    p = subprocess.run([sys.executable, "-c", program], cwd=tmp_path, env=env, capture_output=True,
                       check=True)
    library, last, svg = p.stdout.decode().split("\n", 2)
    assert os.path.realpath(library).startswith(str(tmp_path / "q") + "/")
    assert last == "1.0"
    assert svg == cli(example("rlc.bg"), "--style", "print", "-T", "svg")[1].decode()


def test_site_dir_of_debians_prefixes():
    import sysconfig
    if "deb_system" in sysconfig.get_scheme_names():  # Debian's python3
        assert site_dir("/usr") == "/usr/lib/python3/dist-packages"
        assert site_dir("/usr/local") in sys.path
    assert site_dir("/opt/bg").startswith("/opt/bg/lib/python3.")
