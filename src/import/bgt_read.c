/* SPDX-License-Identifier: BSD-3-Clause */
/* BondGraphTools' YAML (its bgt.save / bgt.load format, file version 0.1 as
 * BondGraphTools 0.4 writes it) into the imported graph. The conventions
 * (every BondGraphTools port takes power in; 1-junction ports are inverting
 * or not; TF/GY port 0 primary, 1 secondary; an exposed SS is a submodel
 * port) are mapped as docs/import.md's table says. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "import/import_int.h"

enum { MAX_NEST = 64, MAX_ARGS = 3 };

typedef struct {
  const char *lib, *comp; /* "base", "R" */
  const char *params[MAX_ARGS];
  const char *defaults[MAX_ARGS]; /* NULL: no default */
} bgt_component;

static const bgt_component library[] = {
    {"base", "R", {"r"}, {"1000"}},
    {"base", "C", {"C"}, {"1000"}},
    {"base", "I", {"L"}, {"2000"}},
    {"base", "Se", {"e"}, {NULL}},
    {"base", "Sf", {"f"}, {NULL}},
    {"base", "TF", {"r"}, {"1"}},
    {"base", "GY", {"R"}, {"1"}},
    {"base", "0", {NULL}, {NULL}},
    {"base", "1", {NULL}, {NULL}},
    {"base", "SS", {"e", "f"}, {NULL}},
    {"BioChem", "Ce", {"k", "R", "T"}, {NULL}},
    {"BioChem", "Re", {"r", "R", "T"}, {NULL}},
    {"elec", "Di", {"Is", "n", "Vt"}, {NULL, "1", "0.0258563"}},
};

typedef struct {
  bg_ig *g;
  bg_diags *dg;
  const bg_ynode *models;
  int *state, *ig_of; /* per entry of models: 0 new, 1 being built, 2 built; its graph model */
  int depth;
} reader;

/* A word of a scalar and where it stands. */
typedef struct {
  const char *s;
  bg_srcloc at;
} word;

static int split_words(bg_ig *g, const bg_ynode *n, word *w, int max) {
  int k = 0;
  const char *s = n->str;
  int one_line = n->plain && !strchr(s, '\n');
  for (size_t i = 0; s[i] && k < max;) {
    while (s[i] && isspace((unsigned char)s[i])) i++;
    if (!s[i]) break;
    size_t j = i;
    while (s[j] && !isspace((unsigned char)s[j])) j++;
    w[k].s = bg_arena_strndup(&g->arena, s + i, j - i);
    w[k].at = (bg_srcloc){n->line, one_line ? n->col + (int)i : n->col, 0};
    k++;
    i = j;
  }
  return k;
}

static bg_srcloc at_node(const bg_ynode *n) { return (bg_srcloc){n->line, n->col, 0}; }

static int is_number(const char *s) {
  if (!*s) return 0;
  char *end;
  errno = 0;
  double v = strtod(s, &end);
  return !*end && isfinite(v) && !(s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) &&
         strspn(s, "0123456789.eE+-") == strlen(s);
}

static int model_entry(const reader *r, const char *key) {
  for (int i = 0; i + 1 < r->models->nkids; i += 2)
    if (r->models->kids[i]->kind == BG_Y_SCALAR && !strcmp(r->models->kids[i]->str, key)) return i / 2;
  return -1;
}

static const bgt_component *find_component(const char *tmpl) {
  const char *slash = strchr(tmpl, '/');
  if (!slash) return NULL;
  for (size_t i = 0; i < sizeof library / sizeof *library; i++)
    if (strlen(library[i].lib) == (size_t)(slash - tmpl) && !strncmp(library[i].lib, tmpl, (size_t)(slash - tmpl)) &&
        !strcmp(library[i].comp, slash + 1))
      return &library[i];
  return NULL;
}

static const bg_ynode *seq_of(reader *r, const bg_ynode *model, const char *key, int required) {
  const bg_ynode *v = bg_yaml_get(model, key);
  if (!v) {
    if (required) bg_diag_error(r->dg, at_node(model), "this model has no '%s:' list", key);
    return NULL;
  }
  if (v->kind == BG_Y_SCALAR && !*v->str) return NULL; /* "netlist:" with nothing */
  if (v->kind != BG_Y_SEQ) {
    bg_diag_error(r->dg, at_node(v), "'%s:' is a list (lines starting with '- ')", key);
    return NULL;
  }
  for (int i = 0; i < v->nkids; i++)
    if (v->kids[i]->kind != BG_Y_SCALAR) {
      bg_diag_error(r->dg, at_node(v->kids[i]), "an item of '%s:' is one line of words", key);
      return NULL;
    }
  return v;
}

/* A param NAME_p of the component, for components with laws. */
static const char *comp_param(reader *r, bg_ig_model *m, const char *comp, const char *p,
                              const char *value, int line) {
  const char *name = bg_ig_name(r->g, m, bg_ig_printf(r->g, "%s_%s", comp, p));
  bg_ig_add_param(m, (bg_ig_param){name, value, NULL, line, 0, 0});
  return name;
}

/* One atomic component: its node (and params) in model mi. */
static int add_component(reader *r, int mi, const bgt_component *c, word *w, int nw) {
  bg_ig *g = r->g;
  const char *val[MAX_ARGS] = {0};
  int nparams = 0;
  while (nparams < MAX_ARGS && c->params[nparams]) nparams++;
  for (int a = 2; a < nw; a++) {
    const char *eq = strchr(w[a].s, '=');
    int slot = -1;
    const char *v = w[a].s;
    if (eq) {
      size_t kl = (size_t)(eq - w[a].s);
      for (int k = 0; k < nparams; k++)
        if (strlen(c->params[k]) == kl && !strncmp(c->params[k], w[a].s, kl)) slot = k;
      for (int k = 0; slot < 0 && k < nparams; k++) /* c=10 for C: BondGraphTools' own examples */
        if (strlen(c->params[k]) == kl && !strncasecmp(c->params[k], w[a].s, kl)) slot = k;
      if (slot < 0) {
        bg_diag_error(r->dg, w[a].at, "%s/%s has no parameter '%.*s'%s%s%s%s%s", c->lib, c->comp,
                      (int)kl, w[a].s, nparams ? " (its parameters: " : "",
                      nparams ? c->params[0] : "", nparams > 1 ? ", " : "",
                      nparams > 1 ? c->params[1] : "", nparams ? (nparams > 2 ? ", ...)" : ")") : "");
        return -1;
      }
      v = eq + 1;
    } else {
      for (int k = 0; k < nparams && slot < 0; k++)
        if (!val[k]) slot = k;
      if (slot < 0) {
        bg_diag_error(r->dg, w[a].at, "%s/%s takes %d parameter%s; '%s' is one too many", c->lib,
                      c->comp, nparams, nparams == 1 ? "" : "s", w[a].s);
        return -1;
      }
    }
    if (!is_number(v)) {
      bg_diag_error(r->dg, w[a].at, "parameter value '%s' is not a number; bgdraw imports numeric "
                    "parameters (a symbol or control variable is given its value in the YAML)", v);
      return -1;
    }
    val[slot] = v;
  }
  for (int k = 0; k < nparams; k++)
    if (!val[k]) val[k] = c->defaults[k];
  bg_ig_model *m = &g->models[mi];
  int line = w[0].at.line;
  bg_ig_node n = {.orig = w[0].s, .line = line};
  n.name = bg_ig_name(g, m, w[0].s);
  if (strcmp(n.name, w[0].s))
    bg_ig_add_note(g, m, line, "component '%s' is called %s here (a .bg name)", w[0].s, n.name);
  const char *k = c->comp;
  if (!strcmp(k, "R") || !strcmp(k, "C") || !strcmp(k, "I") || !strcmp(k, "TF"))
    n.kind = k, n.value = val[0];
  else if (!strcmp(k, "GY")) /* both ports take power in: e0 = R f1, e1 = -R f0 */
    n.kind = "GY", n.value = val[0][0] == '-' ? val[0] + 1 : bg_ig_printf(g, "-%s", val[0]);
  else if (!strcmp(k, "0") || !strcmp(k, "1")) n.kind = k;
  else if (!strcmp(k, "SS")) n.kind = "SS";
  else if (!strcmp(k, "Se") || !strcmp(k, "Sf")) {
    n.kind = k;
    n.sf_value_neg_if_head = k[1] == 'f';
    if (val[0]) n.value = val[0];
    else {
      n.value = comp_param(r, m, n.name, k[1] == 'e' ? "e" : "f", "0", line);
      m->params[m->nparams - 1].desc = "a control variable in BondGraphTools; --set gives its value";
    }
  } else {
    for (int q = 0; q < nparams; q++)
      if (!val[q]) {
        bg_diag_error(r->dg, w[0].at, "%s/%s %s has no value for its parameter '%s' (bgdraw needs "
                      "a number: add %s=VALUE)", c->lib, c->comp, w[0].s, c->params[q], c->params[q]);
        return -1;
      }
    const char *p[MAX_ARGS];
    for (int q = 0; q < nparams; q++) p[q] = comp_param(r, m, n.name, c->params[q], val[q], line);
    if (!strcmp(k, "Ce")) { /* e = R T ln(k q), dq/dt = f (into the species) */
      n.kind = "C";
      n.law = bg_ig_printf(g, "e = %s * %s * log(%s * q)", p[1], p[2], p[0]);
      const char *q0 = comp_param(r, m, n.name, "q0", "1", line);
      m->params[m->nparams - 1].desc = "initial amount: BondGraphTools takes it when simulating; --set changes it";
      n.opts = bg_ig_printf(g, "q0 = %s", q0);
    } else if (!strcmp(k, "Re")) { /* f0 = r (exp(e0/RT) - exp(e1/RT)) = -f1 */
      n.kind = "R", n.sig = "(2)";
      const char *rate = bg_ig_printf(g, "%s * (exp(e1 / (%s * %s)) - exp(e2 / (%s * %s)))", p[0],
                                      p[1], p[2], p[1], p[2]);
      n.law = bg_ig_printf(g, "f1 = %s, f2 = -%s", rate, rate);
    } else { /* Di: f = Is (exp(e / (n Vt)) - 1) */
      n.kind = "R";
      n.law = bg_ig_printf(g, "f = %s * (exp(e / (%s * %s)) - 1)", p[0], p[1], p[2]);
    }
  }
  bg_ig_add_node(m, n);
  return 0;
}

static int build(reader *r, int entry, int mi, bg_srcloc use);

/* The components of one model: instances built first. */
static int add_components(reader *r, int mi, const bg_ynode *comps) {
  for (int i = 0; comps && i < comps->nkids; i++) {
    word w[16];
    int nw = split_words(r->g, comps->kids[i], w, 16);
    if (nw < 2) {
      bg_diag_error(r->dg, at_node(comps->kids[i]), "a component is 'NAME TEMPLATE [PARAM=VALUE ...]' "
                    "(for example 'R1 base/R r=100')");
      return -1;
    }
    if (nw == 16 || (nw > 2 + MAX_ARGS)) {
      bg_diag_error(r->dg, w[nw - 1].at, "too many words in a component");
      return -1;
    }
    bg_ig_model *m = &r->g->models[mi];
    for (int k = 0; k < m->nnodes; k++)
      if (!strcmp(m->nodes[k].orig, w[0].s)) {
        bg_diag_error(r->dg, w[0].at, "component '%s' twice in one model", w[0].s);
        return -1;
      }
    int e = model_entry(r, w[1].s);
    if (e >= 0) {
      if (nw > 2) {
        bg_diag_error(r->dg, w[2].at, "a submodel instance takes no parameters");
        return -1;
      }
      int sub = build(r, e, -1, w[1].at);
      if (sub < 0) return -1;
      m = &r->g->models[mi];
      bg_ig_node n = {.orig = w[0].s, .kind = r->g->models[sub].name, .line = w[0].at.line};
      n.name = bg_ig_name(r->g, m, w[0].s);
      bg_ig_add_node(m, n);
      continue;
    }
    const bgt_component *c = find_component(w[1].s);
    if (!c) {
      bg_diag_error(r->dg, w[1].at, "unknown component '%s': bgdraw imports base/R, base/C, base/I, "
                    "base/Se, base/Sf, base/TF, base/GY, base/0, base/1, base/SS, BioChem/Ce, "
                    "BioChem/Re, elec/Di and the models of this file", w[1].s);
      return -1;
    }
    if (add_component(r, mi, c, w, nw)) return -1;
  }
  return 0;
}

/* ports: "- SSNAME LABEL": the component becomes the submodel's port LABEL. */
static int add_ports(reader *r, int mi, const bg_ynode *ports) {
  for (int i = 0; ports && i < ports->nkids; i++) {
    word w[3];
    int nw = split_words(r->g, ports->kids[i], w, 3);
    if (nw != 2) {
      bg_diag_error(r->dg, at_node(ports->kids[i]), "a port is 'COMPONENT LABEL' (for example 'pin A')");
      return -1;
    }
    bg_ig_model *m = &r->g->models[mi];
    int k = -1;
    for (int j = 0; j < m->nnodes; j++)
      if (!strcmp(m->nodes[j].orig, w[0].s)) k = j;
    if (k < 0) {
      bg_diag_error(r->dg, w[0].at, "no component '%s' in this model to expose", w[0].s);
      return -1;
    }
    if (m->nodes[k].is_port) {
      bg_diag_error(r->dg, w[0].at, "component '%s' exposed twice", w[0].s);
      return -1;
    }
    if (strcmp(m->nodes[k].kind, "SS"))
      bg_ig_add_note(r->g, m, w[0].at.line, "%s (%s) is exposed: it becomes port %s, as BondGraphTools "
                     "replaces it by an SS", w[0].s, m->nodes[k].kind, w[1].s);
    m->nodes[k].name = bg_ig_name(r->g, m, w[1].s);
    m->nodes[k].label = w[1].s;
    m->nodes[k].is_port = 1;
    m->nodes[k].value = NULL;
  }
  return 0;
}

/* One end of a netlist line: the node, the .bg port suffix and what the end
 * demands of the bond's direction. tail: the end written first. */
static int bond_end(reader *r, int mi, const word *w, int tail, int *node, const char **suffix,
                    int *demand) {
  bg_ig *g = r->g;
  bg_ig_model *m = &g->models[mi];
  char *s = bg_arena_strdup(&g->arena, w->s);
  char *dot = strchr(s, '.');
  const char *port = NULL;
  if (dot) *dot = 0, port = dot + 1;
  if (port && strchr(port, '.')) {
    bg_diag_error(r->dg, w->at, "'%s': a bond end is COMPONENT or COMPONENT.PORT", w->s);
    return -1;
  }
  int k = -1;
  for (int j = 0; j < m->nnodes; j++)
    if (!strcmp(m->nodes[j].orig, s)) k = j;
  if (k < 0) {
    bg_diag_error(r->dg, w->at, "no component '%s' in this model", s);
    return -1;
  }
  const bg_ig_node *n = &m->nodes[k];
  int digits = port && *port && strspn(port, "0123456789") == strlen(port);
  *node = k, *suffix = "", *demand = BG_IG_FREE;
  const char *kind = n->kind;
  if (n->is_port || !strcmp(kind, "0")) {
    if (port && !digits) goto bad_port;
  } else if (!strcmp(kind, "1")) {
    if (port && !strcmp(port, "non_inverting")) *demand = BG_IG_HEAD;
    else if (port && !strcmp(port, "inverting")) *demand = BG_IG_TAIL;
    else if (!port || digits) *demand = tail ? BG_IG_TAIL : BG_IG_HEAD;
    else goto bad_port;
  } else if (!strcmp(kind, "TF") || !strcmp(kind, "GY")) {
    if (port && !strcmp(port, "0")) *demand = BG_IG_HEAD;
    else if (port && !strcmp(port, "1")) *demand = BG_IG_TAIL;
    else {
      bg_diag_error(r->dg, w->at, "'%s': say which port of %s %s, %s.0 (primary) or %s.1 (secondary)",
                    w->s, kind, n->orig, n->orig, n->orig);
      return -1;
    }
  } else if (n->sig) { /* Re */
    if (port && (!strcmp(port, "0") || !strcmp(port, "1"))) *suffix = port[0] == '0' ? ".1" : ".2";
    else {
      bg_diag_error(r->dg, w->at, "'%s': say which port of Re %s, %s.0 or %s.1", w->s, n->orig,
                    n->orig, n->orig);
      return -1;
    }
  } else if (!strcmp(kind, "R") || !strcmp(kind, "C") || !strcmp(kind, "I") || !strcmp(kind, "Se") ||
             !strcmp(kind, "Sf") || !strcmp(kind, "SS")) {
    if (port && strcmp(port, "0")) goto bad_port;
  } else { /* an instance: kind is the submodel */
    int sub = -1;
    for (int j = 1; j < g->nmodels; j++)
      if (!strcmp(g->models[j].name, kind)) sub = j;
    if (!port) {
      bg_diag_error(r->dg, w->at, "'%s': say which port of %s, %s.LABEL", w->s, n->orig, n->orig);
      return -1;
    }
    const bg_ig_model *sm = &g->models[sub];
    int p = -1;
    for (int j = 0; j < sm->nnodes; j++)
      if (sm->nodes[j].is_port && !strcmp(sm->nodes[j].label, port)) p = j;
    if (p < 0) goto bad_port;
    *suffix = bg_ig_printf(g, ".%s", sm->nodes[p].name);
    int d = bg_ig_port_direction(sm, sm->nodes[p].name);
    *demand = d < 0 ? BG_IG_FREE : d;
  }
  return 0;
bad_port:
  bg_diag_error(r->dg, w->at, "'%s': %s has no port '%s'", w->s, n->orig, port ? port : "");
  return -1;
}

static int add_netlist(reader *r, int mi, const bg_ynode *net) {
  for (int i = 0; net && i < net->nkids; i++) {
    word w[3];
    int nw = split_words(r->g, net->kids[i], w, 3);
    if (nw != 2) {
      bg_diag_error(r->dg, at_node(net->kids[i]), "a bond is 'TAIL HEAD' (for example 'R1 kcl' or "
                    "'C1 J.inverting')");
      return -1;
    }
    bg_ig_bond b = {.line = w[0].at.line};
    if (bond_end(r, mi, &w[0], 1, &b.a, &b.pa, &b.ca) ||
        bond_end(r, mi, &w[1], 0, &b.b, &b.pb, &b.cb))
      return -1;
    if (b.a == b.b) {
      bg_diag_error(r->dg, w[1].at, "a bond joins %s to itself", w[0].s);
      return -1;
    }
    bg_ig_add_bond(&r->g->models[mi], b);
  }
  return 0;
}

/* Builds entry `entry` of models: into graph model mi (the root: 0), or a
 * new submodel (mi < 0). The graph model's index, or -1. */
static int build(reader *r, int entry, int mi, bg_srcloc use) {
  if (r->state[entry] == 2) return r->ig_of[entry];
  const bg_ynode *key = r->models->kids[2 * entry], *body = r->models->kids[2 * entry + 1];
  if (r->state[entry] == 1) {
    bg_diag_error(r->dg, use, "model '%s' contains itself", key->str);
    return -1;
  }
  if (r->depth >= MAX_NEST) {
    bg_diag_error(r->dg, use, "models nested more than %d deep", MAX_NEST);
    return -1;
  }
  if (body->kind != BG_Y_MAP) {
    bg_diag_error(r->dg, at_node(body), "model '%s' is a mapping with components: and netlist:", key->str);
    return -1;
  }
  r->state[entry] = 1;
  r->depth++;
  if (mi < 0) {
    const char *k = key->str;
    while (*k == '/') k++;
    const char *name = bg_ig_name(r->g, NULL, *k ? k : "sub");
    for (int j = 0; j < r->g->nmodels; j++) /* unique among the submodels */
      if (!strcmp(r->g->models[j].name, name)) name = bg_ig_printf(r->g, "%s_%d", name, r->g->nmodels);
    mi = bg_ig_add_model(r->g, name, key->line);
  }
  r->ig_of[entry] = mi;
  const bg_ynode *comps = seq_of(r, body, "components", 1);
  int bad = r->dg->nerrors > 0 || add_components(r, mi, comps) ||
            add_ports(r, mi, seq_of(r, body, "ports", 0)) ||
            add_netlist(r, mi, seq_of(r, body, "netlist", 0)) || r->dg->nerrors > 0;
  for (int k = 0; k < body->nkids; k += 2) {
    const char *kk = body->kids[k]->str;
    if (!bad && (!kk || (strcmp(kk, "components") && strcmp(kk, "netlist") && strcmp(kk, "ports")))) {
      bg_diag_error(r->dg, at_node(body->kids[k]), "unknown key '%s' in a model (its keys: "
                    "components, netlist, ports)", kk ? kk : "?");
      bad = 1;
    }
  }
  bg_ig_model *m = &r->g->models[mi];
  for (int k = 0; !bad && k < m->nnodes; k++)
    if (!strcmp(m->nodes[k].kind, "SS") && !m->nodes[k].is_port) {
      bg_diag_error(r->dg, (bg_srcloc){m->nodes[k].line, 1, 0}, "SS %s is not exposed: an SS is a "
                    "submodel's port (add it under ports:)", m->nodes[k].orig);
      bad = 1;
    }
  if (!bad) bg_ig_orient(r->g, mi);
  r->depth--;
  r->state[entry] = 2;
  return bad ? -1 : mi;
}

/* bgdraw: a list of .bg statements for the root model (simulate, plot,
 * output, ...), which BondGraphTools' load ignores: what -o m.yaml keeps of
 * a model that BondGraphTools' format cannot say. */
static int add_extra(reader *r, const bg_ynode *list) {
  if (!list) return 0;
  if (list->kind != BG_Y_SEQ) {
    bg_diag_error(r->dg, at_node(list), "bgdraw: is a list of .bg statements");
    return -1;
  }
  bg_ig_model *m = &r->g->models[0];
  m->extra = bg_xcalloc((size_t)list->nkids + 1, sizeof *m->extra);
  m->extra_lines = bg_xcalloc((size_t)list->nkids + 1, sizeof *m->extra_lines);
  for (int i = 0; i < list->nkids; i++) {
    const bg_ynode *s = list->kids[i];
    if (s->kind != BG_Y_SCALAR || strchr(s->str, '\n')) {
      bg_diag_error(r->dg, at_node(s), "an item of bgdraw: is one .bg statement on one line");
      return -1;
    }
    m->extra[m->nextra] = s->str;
    m->extra_lines[m->nextra++] = s->line;
  }
  return 0;
}

int bg_bgt_read(const bg_ynode *doc, bg_ig *g, bg_diags *dg) {
  if (doc->kind != BG_Y_MAP) {
    bg_diag_error(dg, at_node(doc), "a BondGraphTools model is a mapping with root:, version:, models:");
    return -1;
  }
  const bg_ynode *root = bg_yaml_get(doc, "root"), *models = bg_yaml_get(doc, "models"),
                 *version = bg_yaml_get(doc, "version");
  for (int k = 0; k < doc->nkids; k += 2) {
    const char *kk = doc->kids[k]->str;
    if (!kk || (strcmp(kk, "root") && strcmp(kk, "models") && strcmp(kk, "version") &&
                strcmp(kk, "bgdraw"))) {
      bg_diag_error(dg, at_node(doc->kids[k]), "unknown top-level key '%s' (BondGraphTools' keys: "
                    "version, root, models; and bgdraw's own, bgdraw)", kk ? kk : "?");
      return -1;
    }
  }
  if (version && version->kind != BG_Y_SCALAR) {
    bg_diag_error(dg, at_node(version), "version: is the file format's version (0.1)");
    return -1;
  }
  if (!models || models->kind != BG_Y_MAP || !models->nkids) {
    bg_diag_error(dg, models ? at_node(models) : (bg_srcloc){1, 1, 0},
                  "models: is a mapping from model names to models");
    return -1;
  }
  if (root && (root->kind != BG_Y_SCALAR || !*root->str)) {
    bg_diag_error(dg, at_node(root), "root: is the model's name");
    return -1;
  }
  reader r = {g, dg, models, NULL, NULL, 0};
  int entry = model_entry(&r, "/");
  if (entry < 0 && root) entry = model_entry(&r, root->str);
  if (entry < 0) {
    bg_diag_error(dg, root ? at_node(root) : at_node(models), "no root model: models: has neither "
                  "'/' nor '%s'", root ? root->str : "the root's name");
    return -1;
  }
  int n = models->nkids / 2;
  r.state = bg_xcalloc((size_t)n, sizeof *r.state);
  r.ig_of = bg_xcalloc((size_t)n, sizeof *r.ig_of);
  int mi = bg_ig_add_model(g, bg_ig_name(g, NULL, root ? root->str : "model"),
                           root ? root->line : models->line);
  g->models[mi].title = "imported from BondGraphTools";
  if (version && strcmp(version->str, "0.1")) /* 0.1 is what every release writes */
    bg_ig_add_note(g, &g->models[mi], version->line, "file format version %s read as 0.1, "
                   "the format BondGraphTools 0.3 and 0.4 write", version->str);
  int rc = build(&r, entry, mi, at_node(models)) < 0 ? -1 : 0;
  if (!rc) rc = add_extra(&r, bg_yaml_get(doc, "bgdraw"));
  free(r.state), free(r.ig_of);
  return rc;
}
