#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Two hygiene rules of docs/architecture.md, checked on the sources:

1. Every function a file of src/ or render/ defines without `static` is called
   (or taken as a pointer) from some other file: a function only its own file
   uses is static, and a function nobody uses is deleted. Other files are the
   sources of src/ and render/, and the tests, fuzzers and benchmarks (a
   function that only a test calls is a tested interface); a function the
   public header include/bgdraw.h declares is libbgdraw's, for programs outside
   the tree.
2. docs/architecture.md names every source file of src/ and render/ (a .c file
   by its stem or name, a header by its name or the stem of a .c file beside
   it), and every project path it cites in backquotes exists.
3. No call circle among the files of one folder: when a driver and its parts
   share a helper, the helper sits in a file of its own under them, so no
   part calls back into a file that calls it (a file calls another when it
   names a function that file defines). KNOWN_CIRCLES lists what is still
   circular, as notes; a circle not listed fails, and so does a listed one
   that is gone (take it off the list).

The check reads C text with comments and strings removed: a definition is a
line that starts at column 0 with a type and a name and opens a body; a use is
the name as a token anywhere else but a prototype.

usage: symbols_rule.py [ROOT]     exit 0 when the tree keeps both rules
"""
import os
import re
import sys

COMMENT_OR_STRING = re.compile(r'/\*.*?\*/|//[^\n]*|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
                               re.S)
DEFINITION = re.compile(r'^(?!static\b|typedef\b|extern\b|struct\b|enum\b|union\b|return\b|'
                        r'else\b|if\b|for\b|while\b|do\b|switch\b|case\b|default\b|#)'
                        r'[A-Za-z_][\w \t\*]*?\b([A-Za-z_]\w*)\s*\(([^;{}()]|\([^;{}()]*\))*\)'
                        r'\s*(?:__attribute__\s*\(\(.*?\)\)\s*)?\{', re.M | re.S)
TOKEN = re.compile(r'[A-Za-z_]\w*')
# Folders whose findings are notes, not failures, while a rewrite lands in
# steps (issue 27's run object, outputs table and library: landed, so none).
IN_REWRITE = ()
# Circles still to break (rule 3), each as its sorted files.
KNOWN_CIRCLES = set()


def strip(text):
    """Comments and literals out, line breaks kept (so columns and lines stay)."""
    return COMMENT_OR_STRING.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)


PROTOTYPE = re.compile(r'^(?!return\b|else\b|case\b|#)[A-Za-z_][\w \t\*]*?\b[A-Za-z_]\w*\s*'
                       r'\(([^;{}()]|\([^;{}()]*\))*\)\s*(?:__attribute__\s*\(\(.*?\)\)\s*)?;',
                       re.M | re.S)


def prototypes_out(text):
    """Prototypes (at column 0, as the project writes them) are not uses."""
    return PROTOTYPE.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)


def sources(root, tops, exts):
    for top in tops:
        base = os.path.join(root, top)
        for dirpath, dirnames, filenames in os.walk(base):
            dirnames.sort()
            for name in sorted(filenames):
                if name.endswith(exts):
                    path = os.path.join(dirpath, name)
                    yield os.path.relpath(path, root), path


def read_sources(root):
    texts = {}
    for rel, path in sources(root, ("src", "render", "tests", "bench", "contrib"), (".c", ".h")):
        texts[rel] = strip(open(path, encoding="utf-8", errors="replace").read())
    defined = {}  # name -> (file, offset of the name)
    for rel, text in texts.items():
        if not rel.endswith(".c") or not rel.startswith(("src/", "render/")):
            continue
        for m in DEFINITION.finditer(text):
            defined.setdefault(m.group(1), (rel, m.start(1)))
    return texts, defined


def strongly_connected(graph):
    """Tarjan's components of graph {node: set(nodes)}, iteratively."""
    index, low, on, stack, comps, counter = {}, {}, set(), [], [], [0]
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            for w in it:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(sorted(graph.get(w, ())))))
                    break
                if w in on:
                    low[v] = min(low[v], index[w])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[v])
                if low[v] == index[v]:
                    comp = []
                    while True:
                        w = stack.pop()
                        on.discard(w)
                        comp.append(w)
                        if w == v:
                            break
                    comps.append(tuple(sorted(comp)))
    return comps


def circle_problems(texts, defined):
    graph = {}
    for rel, text in texts.items():
        if not rel.endswith(".c") or not rel.startswith(("src/", "render/")):
            continue
        calls = graph.setdefault(rel, set())
        folder = os.path.dirname(rel)
        for m in TOKEN.finditer(prototypes_out(text)):
            home = defined.get(m.group(0))
            if home and home[0] != rel and os.path.dirname(home[0]) == folder:
                calls.add(home[0])
    problems, notes = [], []
    found = {c for c in strongly_connected(graph) if len(c) > 1}
    for c in sorted(found):
        if c in KNOWN_CIRCLES:
            notes.append("known call circle: " + ", ".join(c))
        else:
            problems.append("call circle among %s: move what they share into a file of its "
                            "own under them" % ", ".join(c))
    for c in sorted(KNOWN_CIRCLES - found):
        problems.append("call circle %s is gone: take it off KNOWN_CIRCLES" % ", ".join(c))
    return problems, notes


def symbol_problems(root, texts, defined):
    inside, outside = {}, {}
    for rel, text in texts.items():
        body = prototypes_out(text)
        for m in TOKEN.finditer(body):
            name = m.group(0)
            if name not in defined:
                continue
            home, at = defined[name]
            if rel == home:
                if m.start() != at:
                    inside[name] = inside.get(name, 0) + 1
            else:
                outside[name] = outside.get(name, 0) + 1
    public = set()  # libbgdraw's interface: called by programs outside the tree
    for rel, path in sources(root, ("include",), (".h",)):
        public |= set(TOKEN.findall(strip(open(path, encoding="utf-8").read())))
    problems, notes = [], []
    for name, (home, _) in sorted(defined.items(), key=lambda kv: (kv[1][0], kv[0])):
        if name == "main" or outside.get(name) or name in public:
            continue
        where = notes if home.startswith(IN_REWRITE) else problems
        if inside.get(name):
            where.append("%s: %s is used only in its own file: make it static" % (home, name))
        else:
            where.append("%s: %s is used nowhere: delete it" % (home, name))
    return problems, notes, len(defined)


def doc_problems(root):
    doc_path = os.path.join(root, "docs", "architecture.md")
    doc = open(doc_path, encoding="utf-8").read()
    quoted = set(re.findall(r'`([^`\s]+)`', doc))
    problems = []
    files = [rel for rel, _ in sources(root, ("src", "render"), (".c", ".h"))]
    stems = {os.path.splitext(os.path.basename(f))[0] for f in files if f.endswith(".c")}
    named = 0
    for rel in files:
        name = os.path.basename(rel)
        stem = os.path.splitext(name)[0]
        ok = name in quoted or rel in quoted or (rel.endswith(".c") and stem in quoted) or \
            (rel.endswith(".h") and stem in stems and stem in quoted)
        if ok:
            named += 1
        else:
            problems.append("%s: not in docs/architecture.md" % rel)
    for q in sorted(quoted):
        if "*" in q or "<" in q:
            continue  # a pattern (tests/unit/test_*.c), not a path
        if re.match(r'^(src|render|tests|bench|docs|tools|include|examples|styles|contrib)/', q):
            if not os.path.exists(os.path.join(root, q.rstrip("/"))):
                problems.append("docs/architecture.md cites `%s`, which does not exist" % q)
    return problems, named, len(files)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    texts, defined = read_sources(root)
    sym, notes, nfunc = symbol_problems(root, texts, defined)
    circles, circle_notes = circle_problems(texts, defined)
    sym += circles
    notes += circle_notes
    doc, named, nfiles = doc_problems(root)
    for p in notes:
        print("symbols rule: note: " + p)
    for p in sym + doc:
        print("symbols rule: " + p)
    print("symbols rule: %d extern functions, %d not called from another file; "
          "%d of %d source files in docs/architecture.md, %d doc problems"
          % (nfunc, len(sym), named, nfiles, len(doc)))
    return 1 if sym or doc else 0


if __name__ == "__main__":
    sys.exit(main())
