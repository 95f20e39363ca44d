# SPDX-License-Identifier: BSD-3-Clause
"""How much a run of the property campaign may take (docs/property.md, `robust`).

Every program the checks start (bgdraw, prop_libjson, the C compiler, the
SciPy side, the compiled drivers) is bounded by CPU time, not wall time: a
campaign at nice 19 on a machine loaded by other work gets a small share of
a core, so a run that takes 3 s of CPU can take minutes of wall time and is
no hang (seed 5041's parasitic run passed 120 s of wall time at a load of
15). The bound grows with the model: CPU_BASE + CPU_PER_BOND per bond of
the text run, STIFF times that for the parasitic runs (stiff on purpose).
The kernel enforces it (RLIMIT_CPU: SIGXCPU at the bound, SIGKILL two
seconds later), so a busy loop ends there whatever the load. A wall-time
guard (WALL_FACTOR times the CPU bound, at least WALL_MIN) stays only for a
run that waits without using CPU (a blocked read). PROP_CPU_SCALE
multiplies the bounds for a slower build (the sanitizers' is 3 to 10 times
slower: PROP_CPU_SCALE=5); PROP_WALL sets the guard in seconds (plant.sh's
`block` demonstration).
"""
import math
import os
import re
import resource
import subprocess

CPU_BASE = 10.0      # s of CPU for any run
CPU_PER_BOND = 0.2   # s of CPU more per bond of the model (100 elements: about 130 bonds, 36 s)
STIFF = 4            # a parasitic run: four times the bound
WALL_FACTOR = 20     # the wall-time guard: 20 times the CPU bound ...
WALL_MIN = 600       # ... and at least this
WALL = float(os.environ.get("PROP_WALL", "0"))  # or this, when set
SCALE = float(os.environ.get("PROP_CPU_SCALE", "1"))


def bonds_of(text):
    """The model's size as the bound reads it: its bond statements (a
    submodel's, indented, not counted)."""
    return len(re.findall(r"^bond ", text, re.M))


def cpu_bound(bonds, stiff=False):
    """Seconds of CPU a run of a model with this many bonds may use."""
    return SCALE * (CPU_BASE + CPU_PER_BOND * bonds) * (STIFF if stiff else 1)


def file_bound(path, stiff=False):
    """cpu_bound for the model in the file path."""
    with open(path) as f:
        return cpu_bound(bonds_of(f.read()), stiff)


class Done:
    """A finished (or stopped) run: status (None when it was stopped at a
    bound: `over` says which), stdout and stderr bytes, the CPU it used (its
    own and its children's, user and system)."""

    def __init__(self, status, out, err, cpu, over=None):
        self.status, self.out, self.err, self.cpu, self.over = status, out, err, cpu, over


def _cpu_of(pid):
    """CPU seconds a live process has used so far (/proc), for the message
    of a run stopped by the wall guard: near 0 means it waited."""
    try:
        f = open("/proc/%d/stat" % pid).read().rsplit(")", 1)[1].split()
        return (int(f[11]) + int(f[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return float("nan")


def run(cmd, cpu, stdin=None, cwd=None):
    """Runs cmd with at most cpu seconds of CPU and the wall guard; stdin
    bytes or None (no input). The CPU used is measured as the change of this
    process's children's rusage (a campaign worker runs one program at a
    time)."""
    soft = max(1, math.ceil(cpu))

    # the limits set by util-linux's prlimit, which then runs cmd in its own
    # process: a preexec_fn would make Popen fork this interpreter whole
    # (no vfork), and those forks were half the suite run's CPU (sys 113 s
    # of 234 s for its 300 models); SIGXCPU at soft, SIGKILL at the hard
    # limit, no core file (SIGXCPU dumps one by default)
    limited = ["prlimit", "--cpu=%d:%d" % (soft, soft + 2), "--core=0:0", "--"] + list(cmd)
    wall = WALL or max(WALL_MIN, WALL_FACTOR * cpu)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.Popen(limited, stdin=subprocess.PIPE if stdin is not None else subprocess.DEVNULL,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=cwd)
    try:
        out, err = p.communicate(stdin, timeout=wall)
        over = None
    except subprocess.TimeoutExpired:
        used = _cpu_of(p.pid)
        p.kill()
        out, err = p.communicate()
        over = "no answer within %d s of wall time (%.2f s of CPU used: %s)" % (
            wall, used, "waiting, not computing" if used < 0.1 * cpu else "the machine is very loaded")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    used = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    # SIGXCPU at the bound (the kernel's count; the rusage measured here can
    # read a little less), SIGKILL at the hard limit if it was caught
    if over is None and (p.returncode == -24 or (p.returncode == -9 and used >= soft - 1)):
        over = "more than %d s of CPU (%.1f s measured; the bound for this size)" % (soft, used)
    return Done(None if over else p.returncode, out, err, used, over)
