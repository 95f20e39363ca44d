# SPDX-License-Identifier: BSD-3-Clause
"""Robustness: bgdraw never crashes on damaged input.

Takes every model in examples/, damages it in deterministic random ways
(deleted, duplicated or swapped tokens, truncation, stray characters, a line
joined to the next) and runs `bgdraw MUTANT --check` and `-o x.json` on each.
Every run must end with exit status 0 (the mutant is still a valid model) or 1
(diagnostics on stderr, each with a caret line, and no output file), within
a few seconds, and never with a signal.

usage: python3 tests/mutated_models.py PATH_TO_BGDRAW [COUNT]  (from the project root)
"""
import glob
import os
import random
import re
import subprocess
import sys
import tempfile

STRAY = ["(", ")", "=", ",", "->", "|", "^", "1e999", "-", "*", "\"", "#", "[", "]",
         ":", "0", "table(", "\t", "\\", "\u00e9", "\x00", "nan", "9" * 40]


def mutate(text, rng):
    toks = re.findall(r"\s+|\w+|[^\w\s]+", text)
    how = rng.randrange(7)
    i = rng.randrange(len(toks))
    if how == 0:
        del toks[i]
    elif how == 1:
        toks.insert(i, toks[rng.randrange(len(toks))])
    elif how == 2:
        j = rng.randrange(len(toks))
        toks[i], toks[j] = toks[j], toks[i]
    elif how == 3:
        return "".join(toks)[: rng.randrange(len(text) + 1)]
    elif how == 4:
        toks.insert(i, rng.choice(STRAY))
    elif how == 5:
        s = "".join(toks)
        k = s.find("\n", rng.randrange(len(s)))
        return s if k < 0 else s[:k] + " " + s[k + 1:]
    else:
        toks[i] = rng.choice(STRAY)
    return "".join(toks)


def main(argv):
    exe = os.path.abspath(argv[1])
    count = int(argv[2]) if len(argv) > 2 else 400
    rng = random.Random(20261123)
    models = sorted(glob.glob("examples/*.bg"))
    fails = []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(count):
            src = models[k % len(models)]
            text = open(src, encoding="utf-8").read()
            for _ in range(1 + rng.randrange(3)):
                text = mutate(text, rng)
            path = os.path.join(tmp, "m%d.bg" % k)
            with open(path, "w", encoding="utf-8", errors="surrogateescape") as f:
                f.write(text)
            out = os.path.join(tmp, "x.json")
            for args in (["--check"], ["-o", out]):
                if os.path.exists(out):
                    os.remove(out)
                try:
                    p = subprocess.run([exe, path] + args, capture_output=True, timeout=20,
                                       cwd=tmp)
                except subprocess.TimeoutExpired:
                    fails.append("%s (from %s) %s: timed out" % (path, src, args))
                    continue
                err = p.stderr.decode("utf-8", "replace")
                if p.returncode not in (0, 1):
                    fails.append("%s (from %s) %s: exit %d\n%s" % (path, src, args, p.returncode,
                                                                   err[-2000:]))
                elif p.returncode == 1:
                    if not re.search(r"^\S+:\d+:\d+: error: ", err, re.M) and "error:" not in err:
                        fails.append("%s (from %s): exit 1 without a diagnostic" % (path, src))
                    elif re.search(r":\d+:\d+: error: ", err) and not re.search(r"^ +\| .*\^$", err, re.M):
                        fails.append("%s (from %s): diagnostic without a caret" % (path, src))
                    if os.path.exists(out):
                        fails.append("%s (from %s): output written despite errors" % (path, src))
            if fails and len(fails) > 10:
                break
        if fails:
            keep = "/tmp/bgdraw-mutants"
            os.makedirs(keep, exist_ok=True)
            for f in fails:
                m = f.split(" ")[0]
                if os.path.exists(m):
                    os.replace(m, os.path.join(keep, os.path.basename(m)))
    for f in fails:
        print("FAIL " + f)
    print("%d mutants, %d failures" % (count, len(fails)))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
