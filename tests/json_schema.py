#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks analysis JSON files against the schema of docs/json.md (format
"bgdraw-analysis", version 1): required keys (top level in the schema's
order, and inside every list item), value types and vocabularies,
references (bond numbers, element names, path ids) and a few consistency
rules. Extra keys are allowed (docs/json.md), but the ones bgdraw adds are
checked too.

Usage: json_schema.py FILE.json...   (exit 1 and one line per problem)
"""
import json
import sys

TOP = ["format", "version", "model", "method", "complete", "bonds", "elements",
       "trace", "conflicts", "causal_paths", "causal_loops", "topological_loops",
       "states", "dependent_stores", "algebraic_variables", "form", "index",
       "estimates", "lagrange"]
METHODS = {"scap", "relaxed", "vandijk", "lagrange"}
STROKES = {"to", "from"}
REASONS = {"source", "store", "resistor", "choice", "propagation", "user", "lagrange"}
CAUSALITIES = {"fixed", "integral", "derivative", "resistance", "conductance", "none"}
KINDS = {"Se", "Sf", "MSe", "MSf", "C", "I", "R", "TF", "MTF", "GY", "MGY", "0", "1"}
PATH_KINDS = {"R-R", "C-C", "I-I", "C-I", "C-R", "I-R", "S-*"}
TLOOP_KINDS = {"flat", "open"}
FORMS = {"ode", "dae", "incomplete"}
ESTIMATES = {"time_constant", "natural_frequency"}
NUMERIC_STATUS = {"computed", "singular", "not computed"}


class Checker:
    def __init__(self, name):
        self.name = name
        self.problems = []

    def bad(self, where, msg):
        self.problems.append("%s: %s: %s" % (self.name, where, msg))

    def keys(self, where, obj, required):
        if not isinstance(obj, dict):
            self.bad(where, "not an object")
            return False
        ok = True
        for k in required:
            if k not in obj:
                self.bad(where, "missing key '%s'" % k)
                ok = False
        return ok

    def typ(self, where, v, types, null=False):
        if v is None and null:
            return True
        # bool is an int in Python: keep them apart
        tl = types if isinstance(types, tuple) else (types,)
        if isinstance(v, bool) and bool not in tl:
            self.bad(where, "%r is a boolean" % (v,))
            return False
        if not isinstance(v, types):
            self.bad(where, "%r has the wrong type" % (v,))
            return False
        return True

    def vocab(self, where, v, words):
        if v not in words:
            self.bad(where, "%r is not one of %s" % (v, sorted(w for w in words if w)))

    def list_of(self, where, v, types):
        if not isinstance(v, list):
            self.bad(where, "not a list")
            return []
        for i, x in enumerate(v):
            self.typ("%s[%d]" % (where, i), x, types)
        return v


def check(name, text):
    c = Checker(name)
    try:
        d = json.loads(text, parse_constant=lambda s: c.bad("number", "%s is not JSON" % s))
    except ValueError as e:
        c.bad("json", str(e))
        return c.problems
    if not c.keys("top", d, TOP):
        return c.problems
    # top-level keys in the schema's order, extra keys after them
    order = [k for k in d if k in TOP]
    if order != TOP:
        c.bad("top", "keys out of the schema's order: %s" % order)
    if list(d)[:len(TOP)] != TOP:
        c.bad("top", "extra keys before the schema's keys")
    if d["format"] != "bgdraw-analysis":
        c.bad("format", repr(d["format"]))
    if d["version"] != 1 or isinstance(d["version"], bool):
        c.bad("version", repr(d["version"]))
    c.typ("model", d["model"], str)
    c.vocab("method", d["method"], METHODS)
    c.typ("complete", d["complete"], bool)

    # bonds
    bond_ids = set()
    for i, b in enumerate(c.list_of("bonds", d["bonds"], dict)):
        w = "bonds[%d]" % i
        if not c.keys(w, b, ["id", "from", "to", "stroke", "reason"]):
            continue
        c.typ(w + ".id", b["id"], int)
        if b["id"] in bond_ids:
            c.bad(w, "duplicate bond %r" % b["id"])
        bond_ids.add(b["id"])
        c.typ(w + ".from", b["from"], str)
        c.typ(w + ".to", b["to"], str)
        if b["stroke"] is None:
            # only a bond without a stroke (incomplete causality) or one a
            # Lagrange 1-junction splits has none
            if d["complete"] and d["method"] != "lagrange":
                c.bad(w, "no stroke in a complete causal graph")
            if b["reason"] is not None and b["reason"] != "lagrange":
                c.bad(w + ".reason", "%r without a stroke" % b["reason"])
        else:
            c.vocab(w + ".stroke", b["stroke"], STROKES)
            c.vocab(w + ".reason", b["reason"], REASONS)
        if "step" in b:
            c.typ(w + ".step", b["step"], int)
        if "conflict" in b:
            c.typ(w + ".conflict", b["conflict"], bool)
    if not d["complete"] and all(b.get("stroke") for b in d["bonds"] if isinstance(b, dict)):
        c.bad("complete", "false although every bond has a stroke")

    # elements
    elem_kind = {}
    for i, e in enumerate(c.list_of("elements", d["elements"], dict)):
        w = "elements[%d]" % i
        if not c.keys(w, e, ["name", "kind", "causality", "inverted"]):
            continue
        c.typ(w + ".name", e["name"], str)
        if e["name"] in elem_kind:
            c.bad(w, "duplicate element %r" % e["name"])
        c.vocab(w + ".kind", e["kind"], KINDS)
        elem_kind[e["name"]] = e["kind"]
        c.vocab(w + ".causality", e["causality"], CAUSALITIES)
        c.typ(w + ".inverted", e["inverted"], bool)
        k, caus = e["kind"], e["causality"]
        if k in ("Se", "Sf", "MSe", "MSf") and caus not in ("fixed", "none"):
            c.bad(w, "source with causality %r" % caus)
        if k in ("C", "I") and caus not in ("integral", "derivative", "none"):
            c.bad(w, "store with causality %r" % caus)
        if k == "R" and caus not in ("resistance", "conductance", "none"):
            c.bad(w, "resistor with causality %r" % caus)
        if k in ("0", "1", "TF", "MTF", "GY", "MGY") and caus != "none":
            c.bad(w, "junction-structure node with causality %r" % caus)
    for i, b in enumerate(d["bonds"]):
        if isinstance(b, dict):
            for end in ("from", "to"):
                if b.get(end) not in elem_kind:
                    c.bad("bonds[%d].%s" % (i, end), "unknown element %r" % b.get(end))

    def bonds_ref(where, v, nonempty=True):
        for j, x in enumerate(c.list_of(where, v, int)):
            if x not in bond_ids:
                c.bad("%s[%d]" % (where, j), "unknown bond %r" % x)
        if nonempty and isinstance(v, list) and not v:
            c.bad(where, "empty")

    def elem_ref(where, v):
        if v not in elem_kind:
            c.bad(where, "unknown element %r" % (v,))

    # trace
    for i, t in enumerate(c.list_of("trace", d["trace"], dict)):
        w = "trace[%d]" % i
        if c.keys(w, t, ["step", "text"]):
            if t["step"] != i + 1:
                c.bad(w + ".step", "%r, expected %d" % (t["step"], i + 1))
            c.typ(w + ".text", t["text"], str)
    for i, b in enumerate(d["bonds"]):
        if isinstance(b, dict) and isinstance(b.get("step"), int) and b["step"] > len(d["trace"]):
            c.bad("bonds[%d].step" % i, "no trace step %d" % b["step"])

    # conflicts
    for i, x in enumerate(c.list_of("conflicts", d["conflicts"], dict)):
        w = "conflicts[%d]" % i
        if not c.keys(w, x, ["node", "type", "degree", "bonds"]):
            continue
        elem_ref(w + ".node", x["node"])
        c.vocab(w + ".type", x["type"], {1, 2})
        c.typ(w + ".degree", x["degree"], int)
        bonds_ref(w + ".bonds", x["bonds"])
        if x["type"] == 1 and x["degree"] != 0:
            c.bad(w, "type 1 with degree %r" % x["degree"])
        if x["type"] == 2 and not (isinstance(x["degree"], int) and x["degree"] >= 1):
            c.bad(w, "type 2 with degree %r" % x["degree"])
        junction = elem_kind.get(x["node"]) in ("0", "1")
        if junction and x["type"] == 2 and len(x["bonds"]) != x["degree"] + 1:
            c.bad(w, "type 2 degree %d at a junction lists %d bonds, not k+1"
                  % (x["degree"], len(x["bonds"])))

    # causal paths
    npath = 0
    for i, p in enumerate(c.list_of("causal_paths", d["causal_paths"], dict)):
        w = "causal_paths[%d]" % i
        npath += 1
        if not c.keys(w, p, ["id", "bonds", "ends", "kind", "class", "order"]):
            continue
        if p["id"] != i + 1:
            c.bad(w + ".id", "%r, expected %d" % (p["id"], i + 1))
        bonds_ref(w + ".bonds", p["bonds"])
        ends = c.list_of(w + ".ends", p["ends"], str)
        if len(ends) != 2:
            c.bad(w + ".ends", "not two ends")
        for e in ends:
            elem_ref(w + ".ends", e)
        c.vocab(w + ".kind", p["kind"], PATH_KINDS)
        c.vocab(w + ".class", p["class"], {None, 1, 2})
        c.typ(w + ".order", p["order"], int, null=True)
        src = any(elem_kind.get(e) in ("Se", "Sf", "MSe", "MSf") for e in ends)
        if src != (p["kind"] == "S-*"):
            c.bad(w + ".kind", "%r with ends %s" % (p["kind"], ends))
        if src and p["order"] is not None:
            c.bad(w + ".order", "a path to a source closes no loop: order must be null")
        if p["class"] is not None and p["order"] != 0:
            c.bad(w, "class %r with order %r" % (p["class"], p["order"]))
        if p["class"] == 2 and p["kind"] != "R-R":
            c.bad(w, "class 2 of kind %r" % p["kind"])
        if len(ends) == 2 and all(e in elem_kind for e in ends) and not src:
            letters = sorted(elem_kind[e] for e in ends)
            if p["kind"] != "-".join(letters):
                c.bad(w + ".kind", "%r with ends of kinds %s" % (p["kind"], letters))

    # causal loops
    for i, l in enumerate(c.list_of("causal_loops", d["causal_loops"], dict)):
        w = "causal_loops[%d]" % i
        if not c.keys(w, l, ["id", "bonds", "gain", "gain_value", "class"]):
            continue
        if l["id"] != i + 1:
            c.bad(w + ".id", "%r" % l["id"])
        bonds_ref(w + ".bonds", l["bonds"])
        c.typ(w + ".gain", l["gain"], str)
        c.typ(w + ".gain_value", l["gain_value"], (int, float), null=True)
        c.vocab(w + ".class", l["class"], {4, 5})
        # no "mesh": a closed causal path passes an even number of gyrators, so
        # Brown's causal meshes cannot occur (docs/analysis.md); the key is gone
        if "mesh" in l:
            c.bad(w + ".mesh", "present; causal meshes cannot occur")

    # topological loops
    for i, t in enumerate(c.list_of("topological_loops", d["topological_loops"], dict)):
        w = "topological_loops[%d]" % i
        if not c.keys(w, t, ["id", "kind", "order", "bonds", "signals", "gain", "gain_value",
                             "algebraic", "cause"]):
            continue
        if t["id"] != i + 1:
            c.bad(w + ".id", "%r" % t["id"])
        c.vocab(w + ".kind", t["kind"], TLOOP_KINDS)
        c.typ(w + ".order", t["order"], int)
        bonds_ref(w + ".bonds", t["bonds"], nonempty=False)
        c.list_of(w + ".signals", t["signals"], str)
        if isinstance(t["signals"], list) and not t["signals"]:
            c.bad(w + ".signals", "empty")
        c.typ(w + ".gain", t["gain"], str)
        c.typ(w + ".gain_value", t["gain_value"], (int, float), null=True)
        c.typ(w + ".algebraic", t["algebraic"], bool)
        if t["algebraic"] != (t["order"] == 0):
            c.bad(w, "algebraic %r with order %r" % (t["algebraic"], t["order"]))
        c.typ(w + ".cause", t["cause"], str)
        cause = t["cause"] if isinstance(t["cause"], str) else ""
        if cause.startswith("causal path "):
            k = int(cause.split()[-1])
            if not 1 <= k <= npath:
                c.bad(w + ".cause", "no causal path %d" % k)
        elif cause.startswith("causal loop "):
            k = int(cause.split()[-1])
            if not 1 <= k <= len(d["causal_loops"]):
                c.bad(w + ".cause", "no causal loop %d" % k)

    # summary
    c.list_of("states", d["states"], str)
    for j, s in enumerate(c.list_of("dependent_stores", d["dependent_stores"], str)):
        elem_ref("dependent_stores[%d]" % j, s)
        if elem_kind.get(s) not in ("C", "I"):
            c.bad("dependent_stores[%d]" % j, "%r is not a store" % s)
    c.list_of("algebraic_variables", d["algebraic_variables"], str)
    c.vocab("form", d["form"], FORMS)
    if d["form"] == "incomplete" and d["complete"]:
        c.bad("form", "incomplete although causality is complete")
    if c.keys("index", d["index"], ["predicted", "numeric", "reason"]):
        ix = d["index"]
        c.typ("index.predicted", ix["predicted"], int, null=True)
        c.typ("index.numeric", ix["numeric"], int, null=True)
        c.typ("index.reason", ix["reason"], str, null=True)
        for k in ("predicted", "numeric"):
            if isinstance(ix[k], int) and not isinstance(ix[k], bool) and ix[k] < 0:
                c.bad("index." + k, "negative")
        if "numeric_status" in ix:
            c.vocab("index.numeric_status", ix["numeric_status"], NUMERIC_STATUS)
            if (ix["numeric"] is None) == (ix["numeric_status"] == "computed"):
                c.bad("index", "numeric %r with status %r" % (ix["numeric"], ix["numeric_status"]))
        if d["form"] == "ode" and ix["predicted"] not in (0, None):
            c.bad("index.predicted", "%r for an ODE" % ix["predicted"])
        if "reduction" in ix and c.keys("index.reduction", ix["reduction"],
                                        ["status", "message", "index", "differentiated",
                                         "lost_states", "dummy_derivatives"]):
            rd = ix["reduction"]
            c.vocab("index.reduction.status", rd["status"], ("reduced", "failed"))
            c.typ("index.reduction.message", rd["message"], str)
            c.typ("index.reduction.index", rd["index"], int, null=True)
            for k in ("differentiated", "lost_states", "dummy_derivatives"):
                c.list_of("index.reduction." + k, rd[k], str)
            if rd["status"] == "reduced" and rd["index"] not in (0, 1):
                c.bad("index.reduction.index", "%r after a reduction" % rd["index"])
            if rd["status"] == "reduced" and not rd["differentiated"]:
                c.bad("index.reduction.differentiated", "empty after a reduction")
    for i, e in enumerate(c.list_of("estimates", d["estimates"], dict)):
        w = "estimates[%d]" % i
        if not c.keys(w, e, ["kind", "path", "value"]):
            continue
        c.vocab(w + ".kind", e["kind"], ESTIMATES)
        c.typ(w + ".path", e["path"], int)
        if isinstance(e["path"], int) and not 1 <= e["path"] <= npath:
            c.bad(w + ".path", "no causal path %r" % e["path"])
        c.typ(w + ".value", e["value"], (int, float))
        if isinstance(e["value"], (int, float)) and not e["value"] > 0:
            c.bad(w + ".value", "not positive")
    if c.keys("lagrange", d["lagrange"], ["coordinates", "forces"]):
        co = c.list_of("lagrange.coordinates", d["lagrange"]["coordinates"], str)
        fo = c.list_of("lagrange.forces", d["lagrange"]["forces"], str)
        if len(co) != len(fo):
            c.bad("lagrange", "%d coordinates, %d forces" % (len(co), len(fo)))
        if d["method"] != "lagrange" and co:
            c.bad("lagrange", "coordinates without Lagrange causality")

    # bgdraw's additions
    if "reduced_form" in d:
        c.vocab("reduced_form", d["reduced_form"], {None, "ode", "dae"})
    if "reduced_note" in d:  # only when the symbolic work budget ran out
        c.typ("reduced_note", d["reduced_note"], str)
        if d.get("reduced_form") is not None:
            c.bad("reduced_note", "with reduced_form %r" % d["reduced_form"])
    if "rosenberg_andry" in d and c.keys("rosenberg_andry", d["rosenberg_andry"],
                                         ["disjoint", "satisfied"]):
        ra = d["rosenberg_andry"]
        c.typ("rosenberg_andry.disjoint", ra["disjoint"], bool)
        c.typ("rosenberg_andry.satisfied", ra["satisfied"], bool)
        five = any(isinstance(l, dict) and l.get("class") == 5 for l in d["causal_loops"])
        if ra["satisfied"] != (ra["disjoint"] and not five):
            c.bad("rosenberg_andry", "satisfied %r, disjoint %r, class 5 loop %r"
                  % (ra["satisfied"], ra["disjoint"], five))
    if "form_parameter_dependent" in d:
        c.typ("form_parameter_dependent", d["form_parameter_dependent"], bool)
    if "fields" in d:
        check_fields(c, d, elem_kind, bond_ids)
    if "omitted" in d and c.keys("omitted", d["omitted"],
                                 ["causal_paths", "causal_loops", "topological_loops",
                                  "topological_loops_complete"]):
        for k in ("causal_paths", "causal_loops", "topological_loops"):
            c.typ("omitted." + k, d["omitted"][k], int)
        om = d["omitted"]
        c.typ("omitted.topological_loops_complete", om["topological_loops_complete"], bool)
        if om["topological_loops_complete"] and (om["causal_paths"] or om["causal_loops"]
                                                 or om["topological_loops"]):
            c.bad("omitted", "topological loops said complete although items were left out")
    if "detectors" in d:  # De, Df (docs/format.md): each reads a node of the model
        names = set(elem_kind)
        for i, e in enumerate(c.list_of("detectors", d["detectors"], dict)):
            w = "detectors[%d]" % i
            if not c.keys(w, e, ["name", "kind", "node"]):
                continue
            c.typ(w + ".name", e["name"], str)
            c.vocab(w + ".kind", e["kind"], {"De", "Df"})
            if e["node"] not in names:
                c.bad(w + ".node", "no element %r" % e["node"])
    return c.problems


def check_fields(c, d, elem_kind, bond_ids):
    """Multiport fields: every port an element of the field's kind that names
    its field and port, on a bond that exists, with a causality of its kind;
    mixed_causality true exactly when the ports' causalities differ."""
    by_name = {e["name"]: e for e in d["elements"] if isinstance(e, dict)}
    for i, f in enumerate(c.list_of("fields", d["fields"], dict)):
        w = "fields[%d]" % i
        if not c.keys(w, f, ["name", "kind", "energy", "mixed_causality", "ports"]):
            continue
        c.vocab(w + ".kind", f["kind"], {"C", "R"})
        c.typ(w + ".energy", f["energy"], str, null=True)
        if f["kind"] == "R" and f["energy"] is not None:
            c.bad(w, "an R field with an energy")
        causes = []
        for k, p in enumerate(c.list_of(w + ".ports", f["ports"], dict)):
            wp = "%s.ports[%d]" % (w, k)
            if not c.keys(wp, p, ["name", "number", "element", "bond", "causality", "law",
                                  "law_form"]):
                continue
            e = by_name.get(p["element"])
            if e is None or elem_kind.get(p["element"]) != f["kind"]:
                c.bad(wp + ".element", "not an element of kind %s: %r" % (f["kind"], p["element"]))
            elif e.get("field") != f["name"] or e.get("port") != p["name"]:
                c.bad(wp, "element %r names field %r port %r" % (p["element"], e.get("field"),
                                                                  e.get("port")))
            elif e["causality"] != p["causality"]:
                c.bad(wp + ".causality", "%r, the element's is %r" % (p["causality"], e["causality"]))
            if p["number"] != k + 1:
                c.bad(wp + ".number", "%r, expected %d" % (p["number"], k + 1))
            if p["bond"] not in bond_ids:
                c.bad(wp + ".bond", "unknown bond %r" % p["bond"])
            c.vocab(wp + ".law_form", p["law_form"], {"e", "f"})
            causes.append(p["causality"])
        if f["mixed_causality"] != (len(set(causes)) > 1):
            c.bad(w + ".mixed_causality", "%r with port causalities %r" % (f["mixed_causality"],
                                                                           causes))


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip())
        return 2
    problems = []
    for path in argv[1:]:
        with open(path, encoding="utf-8") as f:
            problems += check(path, f.read())
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
