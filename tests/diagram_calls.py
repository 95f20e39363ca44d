#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The call rule inside render/diagram (docs/developer.md): every file calls
only files of a lower level, never a sibling of its own level or the driver.
A file's functions are its non-static definitions at column 0; a call is the
name followed by '('. Usage: python3 tests/diagram_calls.py ROOT"""
import re, sys, os

LEVELS = [
    ["diagram_base", "diagram_words", "layout_rank", "layout_align", "layout_pack", "layout_ring",
     "layout_maze"],  # leaves
    ["diagram_route_near"],                                    # the router's near index
    ["diagram_route_cost", "diagram_route_grid"],              # its costs; its grid of lines
    ["diagram_route_search", "diagram_route_branch"],          # its A* search; branches
    ["diagram_geom", "diagram_place", "diagram_route", "diagram_route_detour", "diagram_route_nudge",
     "diagram_route_adjacent", "layout_rows"],  # helpers
    ["layout"],                                                # Graphviz
    ["diagram_grid", "diagram_layers", "diagram_marks", "diagram_signals", "diagram_parts",
     "diagram_fields", "diagram_frames", "diagram_dot", "diagram_tips", "diagram_bonds",
     "diagram_route_bonds", "diagram_diagonals", "diagram_restyle"],  # passes
    ["diagram"],                                               # the driver
    ["render", "render_versions"],                             # the front door
]

def main(root):
    folder = os.path.join(root, "render", "diagram")
    level, text = {}, {}
    for k, names in enumerate(LEVELS):
        for n in names:
            level[n] = k
    bad = 0
    for f in sorted(os.listdir(folder)):
        if not f.endswith(".c"):
            continue
        n = f[:-2]
        if n not in level:
            print(f"render/diagram/{f}: not in the call rule's levels (tests/diagram_calls.py)")
            bad += 1
            continue
        src = open(os.path.join(folder, f), encoding="utf-8").read()
        text[n] = re.sub(r"/\*.*?\*/|\"(\\.|[^\"\\])*\"", " ", src, flags=re.S)
    owner = {}
    for n, src in text.items():
        for m in re.finditer(r"^(?!static)[A-Za-z][^;(]*?\b(bg_\w+)\(", src, flags=re.M):
            brace, semi = src.find("{", m.end()), src.find(";", m.end())
            if brace < 0 or (0 <= semi < brace):
                continue  # a declaration, not a definition
            owner.setdefault(m.group(1), n)
    for n, src in text.items():
        for name in sorted(set(re.findall(r"\b(bg_\w+)\s*\(", src))):
            o = owner.get(name)
            if o is None or o == n:
                continue
            if level[o] >= level[n]:
                kind = "a sibling" if level[o] == level[n] else "a higher file"
                print(f"render/diagram/{n}.c calls {name} of {kind}, {o}.c")
                bad += 1
    return 1 if bad else 0

if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
