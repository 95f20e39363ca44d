#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The dependency rule of docs/architecture.md: a file in a stage folder includes
only headers of its own stage and of the stages below it.

The stage order is read from CMakeLists.txt (BG_ENGINE_STAGES, then
BG_RENDER_STAGES, then cli and api on top: api is libbgdraw's public face,
beside cli, and uses nothing of it), so the build and this check cannot disagree.
Every folder of src/ and render/ must be a stage, and every project include is
written "stage/name.h" (a bare "name.h" only for a header of the same folder).

Each engine stage S above base (lang ... transform) has one front door, S/S.h:
the only header of S that a file of another stage includes. The headers S.h
includes from its own folder are parts of the front door; every other header
of S holds cross-file internals and is named *_int.h. Including another
stage's *_int.h is a violation (tests, fuzzers and benchmarks may look inside).

usage: include_rule.py [ROOT]     exit 0 when the tree keeps the rule
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def stage_order(root):
    text = open(os.path.join(root, "CMakeLists.txt")).read()
    order = []
    for var in ("BG_ENGINE_STAGES", "BG_RENDER_STAGES", "BG_FRONT_STAGES"):
        m = re.search(r"set\(%s\s+([^)]*)\)" % var, text)
        if not m:
            sys.exit("include_rule: CMakeLists.txt has no set(%s ...)" % var)
        order += m.group(1).split()
    return order + ["cli", "api"]


def front_door_problems(root, order, home):
    """Engine stages: the front door exists, and each header it does not reach
    is an internal one (*_int.h)."""
    problems = []
    for s in order[1:order.index("scene")]:
        folder = os.path.join(root, home[s], s)
        if not os.path.isdir(folder):
            continue
        door = "%s.h" % s
        if not os.path.exists(os.path.join(folder, door)):
            problems.append("%s/%s/: no front door %s" % (home[s], s, door))
            continue
        seen, todo = set(), [door]
        while todo:
            h = todo.pop()
            if h in seen:
                continue
            seen.add(h)
            text = open(os.path.join(folder, h), encoding="utf-8").read()
            for inc in INCLUDE.findall(text):
                parts = inc.split("/")
                name = parts[-1]
                if (len(parts) == 1 or parts[0] == s) and not name.endswith("_int.h") \
                        and os.path.exists(os.path.join(folder, name)):
                    todo.append(name)
        for name in sorted(os.listdir(folder)):
            if name.endswith(".h") and name not in seen and not name.endswith("_int.h"):
                problems.append("%s/%s/%s: not part of the front door %s/%s, so internal: "
                                "name it *_int.h" % (home[s], s, name, s, door))
    return problems


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    order = stage_order(root)
    rank = {s: i for i, s in enumerate(order)}
    text = open(os.path.join(root, "CMakeLists.txt")).read()
    renders = re.search(r"set\(BG_RENDER_STAGES\s+([^)]*)\)", text).group(1).split()
    home = {s: ("render" if s in renders else "src") for s in order}
    engine = set(order[1:order.index("scene")])
    problems = front_door_problems(root, order, home)
    checked = 0
    for top in ("src", "render"):
        for entry in sorted(os.listdir(os.path.join(root, top))):
            path = os.path.join(root, top, entry)
            if not os.path.isdir(path):
                problems.append("%s/%s: a file outside every stage folder" % (top, entry))
                continue
            if entry not in rank or home[entry] != top:
                problems.append("%s/%s/: not a stage of CMakeLists.txt" % (top, entry))
                continue
            for name in sorted(os.listdir(path)):
                if not name.endswith((".c", ".h")):
                    continue
                rel = "%s/%s/%s" % (top, entry, name)
                text = open(os.path.join(path, name), encoding="utf-8").read()
                for inc in INCLUDE.findall(text):
                    checked += 1
                    parts = inc.split("/")
                    if len(parts) == 1:
                        if not os.path.exists(os.path.join(path, inc)):
                            problems.append('%s: "%s" is not in %s/ (write "stage/%s")'
                                            % (rel, inc, entry, inc))
                        continue
                    if len(parts) != 2 or parts[0] not in rank:
                        problems.append('%s: "%s" names no stage' % (rel, inc))
                        continue
                    if rank[parts[0]] > rank[entry] or (entry == "api" and parts[0] == "cli"):
                        problems.append('%s: stage %s includes "%s" of the higher stage %s'
                                        % (rel, entry, inc, parts[0]))
                    elif parts[0] != entry and parts[1].endswith("_int.h") and parts[0] in engine:
                        problems.append('%s: "%s" is internal to stage %s (include "%s/%s.h")'
                                        % (rel, inc, parts[0], parts[0], parts[0]))
                    elif parts[0] != entry and parts[0] in engine and parts[1] != parts[0] + ".h":
                        problems.append('%s: "%s" is not the front door of stage %s '
                                        '(include "%s/%s.h")' % (rel, inc, parts[0], parts[0], parts[0]))
                    elif not os.path.exists(os.path.join(root, home[parts[0]], inc)):
                        problems.append('%s: "%s" does not exist' % (rel, inc))
    for p in problems:
        print("include rule: " + p)
    print("include rule: %d includes checked, %d violations (stages: %s)"
          % (checked, len(problems), " < ".join(order)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
