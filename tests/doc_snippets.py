# SPDX-License-Identifier: BSD-3-Clause
"""Extracts the snippets of a documentation page so a test runs every one of
them (tests/contrib.sh on docs/integrations.md). Each fenced block must
follow one of these comments:
    <!-- file: PATH [PATH...] -->   the block is a file: written to each PATH
    <!-- run: DIR -->               the block's lines are commands run in DIR (the
                                    blocks of one DIR in page order, one script)
    <!-- output: NAME -->           the block is output the test compares
A fenced block without one is an error (a snippet no test runs).
Usage: python3 doc_snippets.py PAGE OUTDIR [FROM TO]...
Writes the files under OUTDIR, OUTDIR/run-DIR.sh (set -e, cd DIR, the
commands) and OUTDIR/output-NAME.txt; FROM TO pairs are replaced in every
snippet (the installed paths the page shows, by the source tree's)."""
import os
import re
import sys

page, outdir, pairs = sys.argv[1], sys.argv[2], sys.argv[3:]
lines = open(page, encoding="utf-8").read().split("\n")
marker, problems, i, scripts = None, [], 0, set()
while i < len(lines):
    m = re.match(r"<!-- (file|run|output): (.+?) -->$", lines[i])
    if m:
        marker = (m.group(1), m.group(2).split())
        i += 1
        continue
    f = re.match(r"^(`{3,}|~{3,})", lines[i])
    if not f:
        if lines[i].strip():
            marker = None
        i += 1
        continue
    end = i + 1
    while end < len(lines) and not re.match(r"^%s%s*\s*$" % (re.escape(f.group(1)), f.group(1)[0]), lines[end]):
        end += 1
    body = "\n".join(lines[i + 1:end]) + "\n"
    for a, b in zip(pairs[::2], pairs[1::2]):
        body = body.replace(a, b)
    if marker is None:
        problems.append("%s:%d: a code block no test runs (no file/run/output comment)" % (page, i + 1))
    elif marker[0] == "file":
        for path in marker[1]:
            os.makedirs(os.path.dirname(os.path.join(outdir, path)) or outdir, exist_ok=True)
            with open(os.path.join(outdir, path), "w", encoding="utf-8") as out:
                out.write(body)
    elif marker[0] == "run":
        # several blocks may run in one DIR: their commands follow each other in one script
        script = os.path.join(outdir, "run-%s.sh" % marker[1][0])
        first = script not in scripts
        scripts.add(script)
        with open(script, "w" if first else "a", encoding="utf-8") as out:
            if first:
                out.write("set -e\ncd '%s'\n" % os.path.join(outdir, marker[1][0]))
            out.write(body)
    else:
        with open(os.path.join(outdir, "output-%s.txt" % marker[1][0]), "w", encoding="utf-8") as out:
            out.write(body)
    marker = None
    i = end + 1
for p in problems:
    print(p, file=sys.stderr)
sys.exit(1 if problems else 0)
