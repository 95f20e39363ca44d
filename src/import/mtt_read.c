/* SPDX-License-Identifier: BSD-3-Clause */
/* An MTT model (docs/import.md, "MTT") into the imported graph: the drawing's
 * components and bonds (mtt_geom.c) with their label file's constitutive
 * relationships (lin only), numeric parameters from NAME_numpar.txt, inputs
 * from NAME_input.txt, the simulation's span from NAME_simpar.txt, and
 * subsystems (a component type with its own TYPE/TYPE_abg.fig or
 * TYPE_abg.fig beside the model) as submodels whose SS:[NAME] are ports.
 * MTT coerces a port's inside bond to the direction of the bond outside; a
 * submodel is written once for each set of directions its uses need. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/fileio.h"
#include "import/mtt_int.h"

enum { MAX_NEST = 32, MAX_SYSTEMS = 1000, MAX_PORTS = 256 };

typedef struct {
  bg_mtt_sys s;
  int loaded, building;
  char **keys; /* the variants written: port directions ('i', 'o', '-') ... */
  int *mis;    /* ... and their models */
  int nvar;
  const char **pos;   /* after the first build: the .bg parameter of $1, $2, ... */
  int npos;
} sysrec;

typedef struct {
  bg_ig *g;
  bg_diags *dg;
  sysrec **sys;
  int nsys;
  bg_mtt_assign numpar, input, simpar;
  const char *root_type;
  int depth;
} reader;

/* What one build writes into: the model and the names of its params. */
typedef struct {
  reader *r;
  sysrec *sr;
  int mi;
  int root;
  const char **sym, **sym_bg; /* MTT parameter names and their .bg names */
  int nsym, capsym;
  bg_strindex sym_idx;
  int nest; /* numpar values naming numpar values, being declared */
  int *end_node;           /* per bond end (2 * b + end): its node, -1: dropped */
  int *comp_node;          /* per component: its node (junctions, one-ports), -1 */
  char *free_stroke;       /* per bond: its drawn stroke is not kept */
  const char **end_sfx;
} build;

static bg_ig_model *M(build *b) { return &b->r->g->models[b->mi]; }
static bg_arena *A(build *b) { return &b->r->g->arena; }

static int is_number(const char *s) {
  if (!*s) return 0;
  char *end;
  errno = 0;
  strtod(s, &end);
  return !*end && !errno && strspn(s, "0123456789.eE+-") == strlen(s) && isdigit((unsigned char)s[strspn(s, "+-.")]);
}

static int is_name(const char *s) {
  if (!isalpha((unsigned char)*s) && *s != '_') return 0;
  for (; *s; s++)
    if (!isalnum((unsigned char)*s) && *s != '_') return 0;
  return 1;
}

static bg_srcloc at_comp(build *b, const bg_mtt_comp *c) { return (bg_srcloc){c->line, 1, b->sr->s.file}; }

static const bg_mtt_row *label_of(build *b, const bg_mtt_comp *c) {
  if (!c->name) return NULL;
  char key[256];
  snprintf(key, sizeof key, c->port_ss ? "[%s]" : "%s", c->name);
  return bg_mtt_find(&b->sr->s.lbl.rows, key);
}

/* ------------------------------------------------------------ parameters */
/* The .bg name of MTT parameter sym, declared on first use. */
static const char *use_symbol(build *b, const char *sym);

/* An expression of numpar's text with its names made the .bg names of
 * declared params (numpar names it uses are declared too). */
static const char *rename_expr(build *b, const char *e) {
  bg_strbuf out = {0};
  for (const char *p = e; *p;) {
    if (isalpha((unsigned char)*p) || *p == '_') {
      const char *q = p;
      while (isalnum((unsigned char)*q) || *q == '_') q++;
      char *w = bg_arena_strndup(A(b), p, (size_t)(q - p));
      const char *s = *q != '(' && bg_mtt_find(&b->r->numpar.rows, w) ? use_symbol(b, w) : w;
      bg_sb_puts(&out, s);
      p = q;
    } else if (isdigit((unsigned char)*p) || *p == '.') { /* 1e-3 is one number */
      const char *q = p;
      while (isalnum((unsigned char)*q) || *q == '.' ||
             ((*q == '-' || *q == '+') && (q[-1] == 'e' || q[-1] == 'E')))
        q++;
      bg_sb_printf(&out, "%.*s", (int)(q - p), p);
      p = q;
    } else bg_sb_putc(&out, *p++);
  }
  char *s = bg_arena_strdup(A(b), out.s ? out.s : "");
  bg_sb_free(&out);
  return s;
}

enum { MAX_VALUE_NEST = 200 };

static const char *use_symbol(build *b, const char *sym) {
  int found = bg_strindex_lookup(&b->sym_idx, BG_STRKEYS_ARRAY(b->sym), sym);
  if (found >= 0) return b->sym_bg[found];
  if (b->nsym == b->capsym) {
    b->capsym = b->capsym ? 2 * b->capsym : 16;
    b->sym = bg_xrealloc(b->sym, (size_t)b->capsym * sizeof *b->sym);
    b->sym_bg = bg_xrealloc(b->sym_bg, (size_t)b->capsym * sizeof *b->sym_bg);
  }
  /* a param named like a component gets _par: the component keeps MTT's name */
  int clash = 0;
  for (int i = 0; i < b->sr->s.nc; i++) {
    const bg_mtt_comp *c = &b->sr->s.c[i];
    if (c->name && !strcmp(c->name, sym)) clash = 1;
  }
  const char *bgname = bg_ig_name(b->r->g, M(b), clash ? bg_ig_printf(b->r->g, "%s_par", sym) : sym);
  int k = b->nsym++;
  b->sym[k] = sym, b->sym_bg[k] = bgname;
  bg_strindex_add(&b->sym_idx, BG_STRKEYS_ARRAY(b->sym), b->nsym);
  const bg_mtt_row *v = bg_mtt_find(&b->r->numpar.rows, sym);
  bg_ig_param p = {bgname, "1", NULL, b->sr->s.lbl.summary_line, b->sr->s.lbl.file < 0 ? b->sr->s.file : b->sr->s.lbl.file, 0};
  if (!v) p.desc = bg_ig_printf(b->r->g, "MTT parameter %s: no value in %s_numpar.txt, 1 taken", sym, b->r->root_type);
  else if (clash) p.desc = bg_ig_printf(b->r->g, "MTT parameter %s", sym);
  int pi = M(b)->nparams;
  bg_ig_add_param(M(b), p);
  if (v && b->nest >= MAX_VALUE_NEST) {
    bg_diag_error(b->r->dg, (bg_srcloc){v->line, 1, b->r->numpar.file},
                  "MTT parameter file: values naming other values more than %d deep", MAX_VALUE_NEST);
  } else if (v) { /* after adding: its expression may declare more */
    b->nest++;
    const char *val = rename_expr(b, v->f[1]);
    b->nest--;
    M(b)->params[pi].value = val;
    M(b)->params[pi].line = v->line, M(b)->params[pi].file = b->r->numpar.file;
  }
  return bgname;
}

/* A CR argument: a number, an MTT parameter, or $N (the system's Nth
 * argument, named by its #ALIAS $N NAME). */
static const char *arg_expr(build *b, const bg_mtt_comp *c, const char *a) {
  if (is_number(a)) return a;
  if (a[0] == '$' && isdigit((unsigned char)a[1])) {
    const bg_mtt_row *al = bg_mtt_find(&b->sr->s.lbl.aliases, a);
    if (al && is_name(al->f[1])) return use_symbol(b, al->f[1]);
    return use_symbol(b, bg_ig_printf(b->r->g, "par%s", a + 1));
  }
  if (is_name(a)) return use_symbol(b, a);
  bg_diag_error(b->r->dg, at_comp(b, c),
                "MTT model: %s: the argument '%s' is not a number or a parameter name (bgdraw "
                "reads lin's arguments: causality,gain)",
                c->label, a);
  return NULL;
}

static const char *recip(build *b, const char *v) { return bg_ig_printf(b->r->g, "1/%s", v); }

/* The arguments of a lin CR split at commas (at most 3). */
/* MTT's label for a named component the label file does not list (its
 * abg2lbl: the name is the parameter). */
static const char *default_args(build *b, const bg_mtt_comp *c) {
  static const char *const forms[][2] = {{"R", "flow"}, {"C", "effort"}, {"I", "flow"}, {"TF", "flow"},
                                         {"GY", "flow"}, {"EMTF", "flow"}, {"AE", NULL}, {"AF", NULL}};
  for (size_t i = 0; i < sizeof forms / sizeof *forms; i++)
    if (!strcmp(c->type, forms[i][0]))
      return forms[i][1] ? bg_ig_printf(b->r->g, "%s,%s", forms[i][1], c->name) : c->name;
  return NULL;
}

/* The lin arguments of component c: its label's, else the drawing's third
 * field (TYPE:NAME:ARGS), else MTT's default label. 1: no law (an unnamed
 * component, or CR none): MTT's unit law; -1 after an error. */
static int lin_args(build *b, const bg_mtt_comp *c, const char **w, int *nw) {
  const bg_mtt_row *l = label_of(b, c);
  *nw = 0;
  const char *s;
  if (l && l->n >= 2) {
    if (!strcmp(l->f[1], "none")) return 1;
    if (strcmp(l->f[1], "lin")) {
      bg_diag_error(b->r->dg, (bg_srcloc){l->line, 1, b->sr->s.lbl.file},
                    "MTT model: %s has the constitutive relationship '%s'; bgdraw reads 'lin' "
                    "(linear) only: write the law in the .bg model (bgdraw --import ... -o M.bg)",
                    c->label, l->f[1]);
      return -1;
    }
    s = l->n > 2 ? l->f[2] : "";
  } else if (c->cr && strchr(c->cr, '=')) {
    bg_diag_error(b->r->dg, at_comp(b, c),
                  "MTT model: %s:%s: a law written in the drawing is not read; write it in the .bg "
                  "model (bgdraw --import ... -o M.bg)", c->label, c->cr);
    return -1;
  } else if (c->cr) s = c->cr;
  else if (c->name && (s = default_args(b, c))) {
  } else return 1;
  while (*s && *nw < 3) {
    const char *e = strchr(s, ',');
    size_t n = e ? (size_t)(e - s) : strlen(s);
    w[(*nw)++] = bg_arena_strndup(A(b), s, n);
    s = e ? e + 1 : s + n;
  }
  return 0;
}

static int bad_lin(build *b, const bg_mtt_comp *c, const char *want) {
  const bg_mtt_row *l = label_of(b, c);
  bg_diag_error(b->r->dg, (bg_srcloc){l ? l->line : c->line, 1, l ? b->sr->s.lbl.file : b->sr->s.file},
                "MTT model: %s: lin's arguments should be %s", c->label, want);
  return -1;
}

/* A one-port's value: R (flow,r: e = r f; effort,g: f = g e), C
 * (effort,c: q = c e; state,k: e = k q), I (flow,m: p = m f; state,k: f = k p).
 * A store's gain causality other than state is its inverse law's: MTT's lin
 * gives e = q/c (C) and f = p/m (I) for effort and flow alike in integral
 * causality, so effort,m on an I (which MTT's own DC motor writes) is I = m. */
static const char *oneport_value(build *b, const bg_mtt_comp *c, int *err) {
  const char *w[3];
  int n, u = lin_args(b, c, w, &n);
  if (u < 0) return *err = 1, NULL;
  if (u > 0) return *err = -1, "1"; /* -1: no law, not an error */
  char t = c->type[0];
  int known = n == 2 && (!strcmp(w[0], "flow") || !strcmp(w[0], "effort") || (t != 'R' && !strcmp(w[0], "state")));
  if (n != 2 || !known) {
    *err = -bad_lin(b, c, t == 'R' ? "flow,VALUE (e = VALUE f) or effort,VALUE (f = VALUE e)"
                                   : t == 'C' ? "effort,VALUE (q = VALUE e) or state,VALUE (e = VALUE q)"
                                              : "flow,VALUE (p = VALUE f) or state,VALUE (f = VALUE p)");
    return NULL;
  }
  const char *v = arg_expr(b, c, w[1]);
  if (!v) return *err = 1, NULL;
  int inverse = t == 'R' ? !strcmp(w[0], "effort") : !strcmp(w[0], "state");
  return inverse ? recip(b, v) : v;
}

/* ------------------------------------------------------------ nodes */
/* A component's name: its label, or MTT's own name of an unlabelled one:
 * mttR, mtt0, then mtt0_2, mtt0_3 for the later ones of a type, in
 * drawing order. */
static const char *comp_name(build *b, const bg_mtt_comp *c) {
  if (c->name) return c->name;
  int k = 1;
  for (const bg_mtt_comp *o = b->sr->s.c; o < c; o++) k += !o->name && !strcmp(o->type, c->type);
  return k == 1 ? bg_ig_printf(b->r->g, "mtt%s", c->type) : bg_ig_printf(b->r->g, "mtt%s_%d", c->type, k);
}

static int add_node(build *b, const bg_mtt_comp *c, const char *name, const char *kind,
                    const char *value, const char *comment) {
  bg_ig_node n = {0};
  n.name = bg_ig_name(b->r->g, M(b), name);
  n.orig = c->name ? c->name : c->type;
  n.kind = kind;
  n.value = value;
  n.comment = comment;
  n.line = c->line;
  n.file = b->sr->s.file;
  return bg_ig_add_node(M(b), n);
}

/* The bonds of component ci: bond index and end, in drawing order. */
static int bonds_at(build *b, int ci, int *bond, int *end, int max) {
  int n = 0;
  for (int i = 0; i < b->sr->s.nb && n < max; i++)
    for (int k = 0; k < 2; k++)
      if (b->sr->s.b[i].comp[k] == ci) bond[n] = i, end[n] = k, n++;
  return n;
}

static void set_end(build *b, int bond, int end, int node, const char *sfx) {
  b->end_node[2 * bond + end] = node;
  b->end_sfx[2 * bond + end] = sfx ? sfx : "";
}

static int need_bonds(build *b, const bg_mtt_comp *c, int n, int want) {
  if (n == want) return 0;
  bg_diag_error(b->r->dg, at_comp(b, c), "MTT model: %s at (%d, %d) has %d bond%s; it takes %d%s",
                c->label, c->at.x, c->at.y, n, n == 1 ? "" : "s", want,
                want == 1 && c->type[0] != 'S' ? " (bgdraw reads one-port R, C, I)" : "");
  return -1;
}

/* Which port (1..n) each of the bonds of a 2- or 3-port is: its label
 * ([in]/[1], [out]/[2], [mod]/[3]), else MTT's default (the one unlabelled
 * bond pointing in is [in], the one pointing out [out]). */
static int two_port_sides(build *b, const bg_mtt_comp *c, const int *bond, const int *end, int n,
                          int *port) {
  static const char *const names[3][2] = {{"in", "1"}, {"out", "2"}, {"mod", "3"}};
  int seen[4] = {0};
  for (int i = 0; i < n; i++) {
    const char *l = b->sr->s.b[bond[i]].port[end[i]];
    port[i] = 0;
    if (l) {
      for (int k = 0; k < n; k++)
        if (!strcmp(l, names[k][0]) || !strcmp(l, names[k][1])) port[i] = k + 1;
      if (!port[i]) {
        bg_diag_error(b->r->dg, at_comp(b, c), "MTT model: %s has no port [%s]", c->label, l);
        return -1;
      }
    } else port[i] = end[i] == BG_MTT_HEAD ? 1 : 2;
    if (seen[port[i]]++) {
      bg_diag_error(b->r->dg, at_comp(b, c),
                    "MTT model: two bonds of %s at (%d, %d) are its port [%s]; label them "
                    "([in], [out]%s)",
                    c->label, c->at.x, c->at.y, names[port[i] - 1][0], n == 3 ? ", [mod]" : "");
      return -1;
    }
  }
  return 0;
}

/* TF, GY: bgdraw's side 1 is the bond pointing in. lin effort,n on a TF is
 * MTT's e2 = n e1, f1 = n f2 (ports 1, 2): bgdraw's TF n when port 1 is the
 * bond in; flow,n is 1/n. A GY's lin effort,r is e1 = r f2, e2 = r f1. */
static int two_port(build *b, int ci) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  int bond[3], end[3], port[3], n = bonds_at(b, ci, bond, end, 3);
  if (need_bonds(b, c, n, 2)) return -1;
  if (end[0] == end[1]) {
    bg_diag_error(b->r->dg, at_comp(b, c),
                  "MTT model: both bonds of %s at (%d, %d) point %s it; bgdraw's %s takes power "
                  "through (one bond in, one out)",
                  c->label, c->at.x, c->at.y, end[0] == BG_MTT_HEAD ? "into" : "out of", c->type);
    return -1;
  }
  if (two_port_sides(b, c, bond, end, 2, port)) return -1;
  int swapped = (port[0] == 1) != (end[0] == BG_MTT_HEAD); /* MTT's port 1 points out */
  const char *w[3];
  int nw, u = lin_args(b, c, w, &nw);
  if (u < 0) return -1;
  const char *v = "1";
  int is_tf = !strcmp(c->type, "TF");
  if (!u) {
    if (nw != 2 || (strcmp(w[0], "effort") && strcmp(w[0], "flow")))
      return bad_lin(b, c, "effort,VALUE or flow,VALUE");
    if (!(v = arg_expr(b, c, w[1]))) return -1;
    int inverse = !strcmp(w[0], "flow");
    if (is_tf) inverse ^= swapped;
    if (inverse) v = recip(b, v);
  }
  int node = add_node(b, c, comp_name(b, c), c->type, v, NULL);
  for (int i = 0; i < 2; i++) set_end(b, bond[i], end[i], node, NULL);
  return 0;
}

/* AE: f1 = 0, e2 = g e1 (an Sf 0 on the input bond, an MSe on the output);
 * AF: e1 = 0, f2 = g f1. */
static int amplifier(build *b, int ci) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  int bond[3], end[3], port[3], n = bonds_at(b, ci, bond, end, 3);
  if (need_bonds(b, c, n, 2) || two_port_sides(b, c, bond, end, 2, port)) return -1;
  const char *w[3];
  int nw, u = lin_args(b, c, w, &nw);
  if (u < 0) return -1;
  if (!u && nw != 1) return bad_lin(b, c, "the gain alone");
  const char *g = u ? "1" : arg_expr(b, c, w[0]);
  if (!g) return -1;
  int ae = !strcmp(c->type, "AE");
  const char *base = comp_name(b, c);
  int in = add_node(b, c, bg_ig_printf(b->r->g, "%s_in", base), ae ? "Sf" : "Se", "0",
                    ae ? "MTT's AE: no flow at its input" : "MTT's AF: no effort at its input");
  const char *inname = M(b)->nodes[in].name;
  int out = add_node(b, c, base, ae ? "MSe" : "MSf",
                     bg_ig_printf(b->r->g, "%s * %s.%c", g, inname, ae ? 'e' : 'f'), NULL);
  for (int i = 0; i < 2; i++) set_end(b, bond[i], end[i], port[i] == 1 ? in : out, NULL);
  return 0;
}

/* EMTF: a TF whose modulus is scaled by the effort at port 3 (no flow there). */
static int emtf(build *b, int ci) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  int bond[3], end[3], port[3], n = bonds_at(b, ci, bond, end, 3);
  if (need_bonds(b, c, n, 3)) return -1;
  if (two_port_sides(b, c, bond, end, 3, port)) return -1;
  int i1 = -1, i2 = -1, i3 = -1;
  for (int i = 0; i < 3; i++) *(port[i] == 1 ? &i1 : port[i] == 2 ? &i2 : &i3) = i;
  if (i3 < 0 || end[i1] == end[i2]) {
    bg_diag_error(b->r->dg, at_comp(b, c),
                  "MTT model: %s at (%d, %d): label its modulating bond [mod]; of the other two "
                  "one points in ([in]) and one out ([out])",
                  c->label, c->at.x, c->at.y);
    return -1;
  }
  const char *w[3];
  int nw, u = lin_args(b, c, w, &nw);
  if (u < 0) return -1;
  const char *base = comp_name(b, c);
  int mod = add_node(b, c, bg_ig_printf(b->r->g, "%s_mod", base), "Sf", "0",
                     "MTT's EMTF: no flow at its modulating port");
  const char *m = bg_ig_printf(b->r->g, "%s.e", M(b)->nodes[mod].name);
  const char *k = NULL;
  int inverse = 0;
  if (!u) {
    if (nw < 1 || nw > 2 || (strcmp(w[0], "effort") && strcmp(w[0], "flow")))
      return bad_lin(b, c, "effort or flow, and a gain: effort,VALUE");
    inverse = !strcmp(w[0], "flow");
    if (nw == 2 && !(k = arg_expr(b, c, w[1]))) return -1;
  }
  inverse ^= end[i1] != BG_MTT_HEAD;
  const char *n_ = k ? bg_ig_printf(b->r->g, "%s * %s", k, m) : m;
  if (inverse) n_ = bg_ig_printf(b->r->g, "1/(%s)", n_);
  int node = add_node(b, c, base, "MTF", n_, NULL);
  set_end(b, bond[i1], end[i1], node, NULL);
  set_end(b, bond[i2], end[i2], node, NULL);
  set_end(b, bond[i3], end[i3], mod, NULL);
  return 0;
}

/* De, Df: a detector of the junction it is bonded to (the bond carries no
 * power); on anything else an Sf 0 (De) or Se 0 (Df) with the detector on it. */
static int detector(build *b, int ci, int *junction_bonds) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  int bond[2], end[2], n = bonds_at(b, ci, bond, end, 2);
  if (need_bonds(b, c, n, 1)) return -1;
  int de = !strcmp(c->type, "De");
  const bg_mtt_bond *bd = &b->sr->s.b[bond[0]];
  int other = bd->comp[1 - end[0]];
  const bg_mtt_comp *oc = &b->sr->s.c[other];
  const char *name = bg_ig_name(b->r->g, M(b), comp_name(b, c));
  if (!strcmp(oc->type, de ? "0" : "1") && junction_bonds[other] > 2) {
    junction_bonds[other]--;
    set_end(b, bond[0], 0, -1, NULL), set_end(b, bond[0], 1, -1, NULL);
    bg_ig_add_extra(M(b), b->sr->s.file, c->line,
                    bg_ig_printf(b->r->g, "%s %s = %s", de ? "De" : "Df", name,
                                 M(b)->nodes[b->comp_node[other]].name));
    return 0;
  }
  int s = add_node(b, c, bg_ig_printf(b->r->g, "%s_s", name), de ? "Sf" : "Se", "0",
                   de ? "MTT's De: no flow" : "MTT's Df: no effort");
  set_end(b, bond[0], end[0], s, NULL);
  bg_ig_add_extra(M(b), b->sr->s.file, c->line,
                  bg_ig_printf(b->r->g, "%s %s = %s", de ? "De" : "Df", name, M(b)->nodes[s].name));
  return 0;
}

/* SS: an effort or flow source by its label's attributes (effort,flow:
 * external, internal, a value, or the algebraic loop's zero/unknown), or by
 * its stroke when both are external; a sensed external variable gets a
 * detector NAME_y. */
enum { AT_EXT, AT_INT, AT_ZERO, AT_UNK, AT_VAL };
static int attr(const char *a) {
  return !strcmp(a, "external") ? AT_EXT : !strcmp(a, "internal") ? AT_INT : !strcmp(a, "zero") ? AT_ZERO
         : !strcmp(a, "unknown") ? AT_UNK : AT_VAL;
}

static const char *input_value(build *b, const bg_mtt_comp *c, const char *name) {
  const char *u = bg_ig_printf(b->r->g, "%s_u", name);
  const bg_mtt_row *in = b->root ? bg_mtt_find(&b->r->input.rows,
                                               bg_ig_printf(b->r->g, "%s__%s", b->r->root_type, c->name ? c->name : c->type))
                                 : NULL;
  bg_ig_param p = {bg_ig_name(b->r->g, M(b), u), "0", NULL, c->line, b->sr->s.file, 0};
  if (in) p.value = in->f[1], p.line = in->line, p.file = b->r->input.file, p.is_input = 1;
  else p.desc = bg_ig_printf(b->r->g, "the input of MTT's %s: not in %s_input.txt, 0 taken", c->label, b->r->root_type);
  bg_ig_add_param(M(b), p);
  return p.name;
}

static int source(build *b, int ci) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  int bond[2], end[2], n = bonds_at(b, ci, bond, end, 2);
  if (need_bonds(b, c, n, 1)) return -1;
  const bg_mtt_row *l = label_of(b, c);
  const char *ea = "external", *fa = "external";
  if (l && l->n >= 2) {
    if (!strcmp(l->f[1], "SS")) {
      const char *s = l->n > 2 ? l->f[2] : "";
      const char *comma = strchr(s, ',');
      if (!comma || strchr(comma + 1, ',')) {
        bg_diag_error(b->r->dg, (bg_srcloc){l->line, 1, b->sr->s.lbl.file},
                      "MTT model: %s: an SS label takes two attributes, effort,flow (e.g. "
                      "external,internal)", c->label);
        return -1;
      }
      ea = bg_arena_strndup(A(b), s, (size_t)(comma - s)), fa = comma + 1;
    } else ea = l->f[1], fa = l->n > 2 ? l->f[2] : "external"; /* old style: SS's attributes as CR and args */
  }
  const bg_mtt_bond *bd = &b->sr->s.b[bond[0]];
  int k = end[0];
  int at_ss = bd->stroke[k] || bd->half_e[k] || bd->half_f[k];
  int at_far = bd->stroke[1 - k] || bd->half_e[1 - k] || bd->half_f[1 - k];
  int ke = attr(ea), kf = attr(fa);
  const char *kind = NULL, *value = NULL, *comment = NULL;
  char det = 0;
  const char *name = comp_name(b, c);
  if (ke == AT_VAL && (kf == AT_EXT || kf == AT_INT)) kind = "Se", value = arg_expr(b, c, ea), det = kf == AT_EXT ? 'f' : 0;
  else if (kf == AT_VAL && (ke == AT_EXT || ke == AT_INT)) kind = "Sf", value = arg_expr(b, c, fa), det = ke == AT_EXT ? 'e' : 0;
  else if (ke == AT_ZERO && kf == AT_UNK) kind = "Se", value = "0", comment = "MTT's algebraic-loop SS (zero,unknown): zero effort";
  else if (ke == AT_UNK && kf == AT_ZERO) kind = "Sf", value = "0", comment = "MTT's algebraic-loop SS (unknown,zero): zero flow";
  if (value && !strcmp(value, "0") && comment) /* its stroke chose MTT's way of solving the loop: bgdraw solves it itself */
    b->free_stroke[bond[0]] = 1;
  else if (ke == AT_EXT && kf == AT_INT) kind = "Se";
  else if (ke == AT_INT && kf == AT_EXT) kind = "Sf";
  else if (ke == AT_EXT && kf == AT_EXT && at_far != at_ss) kind = at_far ? "Se" : "Sf", det = at_far ? 'f' : 'e';
  if (!kind) {
    bg_diag_error(b->r->dg, l ? (bg_srcloc){l->line, 1, b->sr->s.lbl.file} : at_comp(b, c),
                  "MTT model: %s at (%d, %d) with attributes %s,%s: %s", c->label, c->at.x, c->at.y,
                  ea, fa,
                  ke == AT_EXT && kf == AT_EXT
                      ? "say which variable it imposes: a causal stroke on its bond, or a label "
                        "such as external,internal (an effort input) or internal,external (a flow input)"
                      : "bgdraw reads one imposed variable (a value, or external with the other "
                        "internal or external), or zero,unknown / unknown,zero");
    return -1;
  }
  if ((ke == AT_VAL || kf == AT_VAL) && !value) return -1;
  if (!value) value = input_value(b, c, name);
  int node = add_node(b, c, name, kind, value, comment);
  set_end(b, bond[0], end[0], node, NULL);
  if (det)
    bg_ig_add_extra(M(b), b->sr->s.file, c->line,
                    bg_ig_printf(b->r->g, "%s %s = %s", det == 'e' ? "De" : "Df",
                                 bg_ig_name(b->r->g, M(b), bg_ig_printf(b->r->g, "%s_y", name)),
                                 M(b)->nodes[node].name));
  return 0;
}

/* Se, Se (MTT's library sources: an SS of fixed causality): the label's
 * argument is the value; none, or "external", is an input. */
static int plain_source(build *b, int ci) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  int bond[2], end[2], n = bonds_at(b, ci, bond, end, 2);
  if (need_bonds(b, c, n, 1)) return -1;
  const bg_mtt_row *l = label_of(b, c);
  const char *name = comp_name(b, c), *v;
  if (l && l->n > 2 && strcmp(l->f[2], "external")) {
    const char *semi = strchr(l->f[2], ';');
    v = arg_expr(b, c, semi ? bg_arena_strndup(A(b), l->f[2], (size_t)(semi - l->f[2])) : l->f[2]);
    if (!v) return -1;
  } else v = input_value(b, c, name);
  set_end(b, bond[0], end[0], add_node(b, c, name, c->type, v, NULL), NULL);
  return 0;
}

/* ------------------------------------------------------------ subsystems */
static int build_sys(reader *r, sysrec *sr, const char *key, int root);

static int exists(const char *p) {
  struct stat st;
  return !stat(p, &st) && S_ISREG(st.st_mode);
}

static char *join(const char *dir, const char *a, const char *b, const char *c) {
  size_t n = strlen(dir) + strlen(a) + strlen(b) + strlen(c) + 2;
  char *s = bg_xmalloc(n);
  snprintf(s, n, "%s%s%s%s%s", dir, *dir ? "/" : "", a, b, c);
  return s;
}

static int load_sys(reader *r, sysrec *sr, const char *path, const char *src, size_t len, int file) {
  bg_fig fig;
  int rc = bg_fig_parse(src, len, &r->g->arena, r->dg, file, &fig);
  sr->s.file = file;
  if (!rc) rc = bg_mtt_geometry(&sr->s, &fig, &r->g->arena, r->dg);
  free(fig.objs);
  char *lbl = join(sr->s.dir, sr->s.type, "_lbl.txt", "");
  (void)path;
  if (!rc) rc = bg_mtt_read_lbl(lbl, &r->g->arena, r->dg, &sr->s.lbl);
  free(lbl);
  sr->loaded = rc ? -1 : 1;
  return rc;
}

/* The subsystem TYPE used from folder dir: TYPE/TYPE_abg.fig there, else
 * TYPE_abg.fig beside the user. NULL when neither exists. */
static sysrec *find_sys(reader *r, const char *dir, const char *type, bg_srcloc use) {
  char *p = join(dir, type, "/", "");
  char *path = join(p, type, "_abg.fig", ""), *sub = p;
  if (!exists(path)) {
    free(path), free(sub);
    sub = join(dir, "", "", "");
    if (*sub) sub[strlen(sub) - 1] = 0; /* join added a '/' */
    path = join(dir, type, "_abg.fig", "");
    if (!exists(path)) {
      free(path), free(sub);
      return NULL;
    }
  } else sub[strlen(sub) - 1] = 0; /* the folder without its '/' */
  for (int i = 0; i < r->nsys; i++)
    if (!strcmp(r->sys[i]->s.type, type) && !strcmp(r->sys[i]->s.dir, sub)) {
      free(path), free(sub);
      return r->sys[i];
    }
  if (r->nsys >= MAX_SYSTEMS) {
    bg_diag_error(r->dg, use, "MTT model: more than %d subsystems", MAX_SYSTEMS);
    free(path), free(sub);
    return NULL;
  }
  sysrec *sr = calloc(1, sizeof *sr);
  if (!sr) BG_FATAL("out of memory");
  sr->s.type = bg_arena_strdup(&r->g->arena, type);
  sr->s.dir = bg_arena_strdup(&r->g->arena, sub);
  r->sys = bg_xrealloc(r->sys, (size_t)(r->nsys + 1) * sizeof *r->sys);
  r->sys[r->nsys++] = sr;
  size_t len = 0;
  char *text = bg_read_file(path, &len);
  if (!text) {
    bg_diag_error(r->dg, use, "cannot read %s: %s", path, bg_file_strerror(errno));
    sr->loaded = -1;
  } else {
    int file = bg_diags_add_source(r->dg, path, text, len);
    load_sys(r, sr, path, text, len, file);
    free(text);
  }
  free(path), free(sub);
  return sr;
}

/* The real name of port label l of subsystem s (its #ALIAS short|short real). */
static const char *unalias(const bg_mtt_sys *s, const char *l) {
  for (int i = 0; i < s->lbl.aliases.n; i++) {
    const bg_mtt_row *a = &s->lbl.aliases.v[i];
    if (a->f[0][0] == '$' || strchr(a->f[1], '/')) continue;
    for (const char *p = a->f[0]; *p;) {
      const char *e = strchr(p, '|');
      size_t n = e ? (size_t)(e - p) : strlen(p);
      if (n == strlen(l) && !strncmp(p, l, n)) return a->f[1];
      p = e ? e + 1 : p + n;
    }
  }
  return l;
}

static int instance(build *b, int ci) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  reader *r = b->r;
  sysrec *child = find_sys(r, b->sr->s.dir, c->type, at_comp(b, c));
  if (!child) {
    bg_diag_error(r->dg, at_comp(b, c),
                  "MTT model: %s at (%d, %d): no component type '%s' (bgdraw knows R, C, I, SS, "
                  "Se, Sf, TF, GY, AE, AF, EMTF, De, Df, 0, 1, and subsystems drawn in %s/%s_abg.fig "
                  "or %s_abg.fig)",
                  c->label, c->at.x, c->at.y, c->type, c->type, c->type, c->type);
    return -1;
  }
  if (child->loaded < 0) return -1;
  int ports[MAX_PORTS], nports = 0;
  for (int i = 0; i < child->s.nc && nports < MAX_PORTS; i++)
    if (child->s.c[i].port_ss) ports[nports++] = i;
  int bond[MAX_PORTS], end[MAX_PORTS], n = bonds_at(b, ci, bond, end, MAX_PORTS);
  char key[MAX_PORTS + 1];
  memset(key, '-', (size_t)nports);
  key[nports] = 0;
  int which[MAX_PORTS];
  for (int i = 0; i < n; i++) {
    const char *l = b->sr->s.b[bond[i]].port[end[i]];
    const char *real = unalias(&child->s, l ? l : end[i] == BG_MTT_HEAD ? "in" : "out");
    which[i] = -1;
    for (int k = 0; k < nports; k++)
      if (!strcmp(child->s.c[ports[k]].name, real)) which[i] = k;
    if (which[i] < 0 || key[which[i]] != '-') {
      bg_diag_error(r->dg, at_comp(b, c),
                    which[i] < 0 ? "MTT model: %s at (%d, %d): its subsystem has no port [%s]%s"
                                 : "MTT model: %s at (%d, %d): two bonds at its port [%s]%s",
                    c->label, c->at.x, c->at.y, real,
                    l ? "" : " (an unlabelled bond is [in] when it points in, [out] when out)");
      return -1;
    }
    key[which[i]] = end[i] == BG_MTT_HEAD ? 'i' : 'o';
  }
  if (r->depth >= MAX_NEST) {
    bg_diag_error(r->dg, at_comp(b, c), "MTT model: subsystems nested more than %d deep", MAX_NEST);
    return -1;
  }
  r->depth++;
  int mi = build_sys(r, child, key, 0);
  r->depth--;
  if (mi < 0) return -1;
  /* the arguments: the label's a;b;c are the subsystem's $1, $2, $3 */
  const bg_mtt_row *l = label_of(b, c);
  bg_strbuf args = {0};
  if (l && l->n > 2) {
    const char *s = l->f[2];
    for (int k = 0; *s; k++) {
      const char *e = strchr(s, ';');
      size_t len = e ? (size_t)(e - s) : strlen(s);
      const char *a = bg_arena_strndup(A(b), s, len);
      if (k >= child->npos || !child->pos[k]) {
        char dollar[16];
        snprintf(dollar, sizeof dollar, "$%d", k + 1);
        const bg_mtt_row *al = bg_mtt_find(&child->s.lbl.aliases, dollar);
        if (al)
          bg_diag_error(r->dg, (bg_srcloc){l->line, 1, b->sr->s.lbl.file},
                        "MTT model: %s: argument %d ('%s') replaces '%s' in %s_lbl.txt, a group of "
                        "CR arguments; bgdraw passes single parameters ($N standing for one name)",
                        c->label, k + 1, a, al->f[1], child->s.type);
        else
          bg_diag_error(r->dg, (bg_srcloc){l->line, 1, b->sr->s.lbl.file},
                        "MTT model: %s: argument %d ('%s') has no #ALIAS $%d NAME in %s_lbl.txt",
                        c->label, k + 1, a, k + 1, child->s.type);
        bg_sb_free(&args);
        return -1;
      }
      const char *v = arg_expr(b, c, a);
      if (!v) {
        bg_sb_free(&args);
        return -1;
      }
      bg_sb_printf(&args, "%s%s = %s", k ? ", " : "(", child->pos[k], v);
      s = e ? e + 1 : s + len;
    }
  }
  if (args.len) bg_sb_putc(&args, ')');
  int node = add_node(b, c, comp_name(b, c), r->g->models[mi].name, NULL, NULL);
  if (args.len) M(b)->nodes[node].sig = bg_arena_strdup(A(b), args.s);
  bg_sb_free(&args);
  const bg_ig_model *cm = &r->g->models[mi];
  for (int i = 0; i < n; i++) {
    const char *pname = child->s.c[ports[which[i]]].name;
    for (int k = 0; k < cm->nnodes; k++)
      if (cm->nodes[k].is_port && !strcmp(cm->nodes[k].orig, pname))
        set_end(b, bond[i], end[i], node, bg_ig_printf(r->g, ".%s", cm->nodes[k].name));
  }
  return 0;
}

/* ------------------------------------------------------------ a system */
static int component(build *b, int ci, int *junction_bonds) {
  const bg_mtt_comp *c = &b->sr->s.c[ci];
  const char *t = c->type;
  if (strchr(t, '*') || (c->name && strchr(c->name, '*'))) {
    bg_diag_error(b->r->dg, at_comp(b, c),
                  "MTT model: %s at (%d, %d): repeated components (TYPE*N) are not read; draw "
                  "the chain", c->label, c->at.x, c->at.y);
    return -1;
  }
  if (!strcmp(t, "0") || !strcmp(t, "1")) return 0; /* the first pass made them */
  if (!strcmp(t, "R") || !strcmp(t, "C") || !strcmp(t, "I")) {
    int bond[2], end[2], n = bonds_at(b, ci, bond, end, 2), err = 0;
    if (need_bonds(b, c, n, 1)) return -1;
    const char *v = oneport_value(b, c, &err);
    if (err > 0) return -1;
    int node = add_node(b, c, comp_name(b, c), t, v, err < 0 ? "no law (unnamed, or CR none): MTT's unit law" : NULL);
    set_end(b, bond[0], end[0], node, NULL);
    b->comp_node[ci] = node;
    return 0;
  }
  if (!strcmp(t, "SS")) {
    if (c->port_ss && !b->root) {
      int bond[2], end[2], n = bonds_at(b, ci, bond, end, 2);
      if (need_bonds(b, c, n, 1)) return -1;
      int node = add_node(b, c, c->name, "port", NULL, NULL);
      M(b)->nodes[node].is_port = 1;
      set_end(b, bond[0], end[0], node, NULL);
      return 0;
    }
    return source(b, ci);
  }
  if (!strcmp(t, "Se") || !strcmp(t, "Sf")) return plain_source(b, ci);
  if (!strcmp(t, "TF") || !strcmp(t, "GY")) return two_port(b, ci);
  if (!strcmp(t, "AE") || !strcmp(t, "AF")) return amplifier(b, ci);
  if (!strcmp(t, "EMTF")) return emtf(b, ci);
  if (!strcmp(t, "De") || !strcmp(t, "Df")) return detector(b, ci, junction_bonds);
  return instance(b, ci);
}

/* The system's bonds as .bg bonds; a port's inside bond takes the direction
 * key asks for (MTT's coerced direction). */
static int bonds(build *b, const char *key) {
  const bg_mtt_sys *s = &b->sr->s;
  int rc = 0, port = 0;
  char *flip = calloc((size_t)s->nb + 1, 1);
  if (!flip) BG_FATAL("out of memory");
  for (int i = 0; key && i < s->nc; i++) {
    if (!s->c[i].port_ss) continue;
    char want = key[port++];
    for (int j = 0; j < s->nb; j++) {
      if (s->b[j].comp[BG_MTT_HEAD] == i && want == 'i') flip[j] = 1;
      if (s->b[j].comp[BG_MTT_TAIL] == i && want == 'o') flip[j] = 1;
    }
  }
  for (int j = 0; j < s->nb; j++) {
    const bg_mtt_bond *bd = &s->b[j];
    int h = 2 * j + BG_MTT_HEAD, t = 2 * j + BG_MTT_TAIL;
    if (b->end_node[h] < 0 || b->end_node[t] < 0) continue;
    if (b->free_stroke[j]) {
      bg_ig_add_bond(M(b), (bg_ig_bond){b->end_node[t], b->end_node[h], b->end_sfx[t], b->end_sfx[h],
                                        BG_IG_FREE, BG_IG_FREE, bd->line, s->file, 0});
      continue;
    }
    if (bd->stroke[0] && bd->stroke[1]) {
      bg_diag_error(b->r->dg, (bg_srcloc){bd->line, 1, s->file},
                    "MTT drawing: the bond from (%d, %d) to (%d, %d) has a causal stroke at both ends",
                    bd->end[1].x, bd->end[1].y, bd->end[0].x, bd->end[0].y);
      rc = -1;
      continue;
    }
    for (int k = 0; k < 2; k++)
      if (!bd->stroke[k] && (bd->half_e[k] || bd->half_f[k])) {
        const char *msg = bg_ig_printf(b->r->g, "a half stroke (%s) at (%d, %d) is not read: bgdraw has no "
                                       "bicausal bonds, it assigns that bond's causality itself",
                                       bd->half_e[k] ? "effort side" : "flow side", bd->end[k].x, bd->end[k].y);
        bg_diag_warning(b->r->dg, (bg_srcloc){bd->line, 1, s->file}, "MTT drawing: %s", msg);
        bg_ig_add_note(b->r->g, M(b), 0, "%s_abg.fig:%d: %s", s->type, bd->line, msg);
      }
    bg_ig_bond bond = {b->end_node[t], b->end_node[h], b->end_sfx[t], b->end_sfx[h], BG_IG_FREE, BG_IG_FREE,
                       bd->line, s->file, bd->stroke[0] ? BG_IG_HEAD : bd->stroke[1] ? BG_IG_TAIL : 0};
    if (flip[j])
      bond = (bg_ig_bond){bond.b, bond.a, bond.pb, bond.pa, BG_IG_FREE, BG_IG_FREE, bond.line, bond.file,
                          bond.stroke == BG_IG_HEAD ? BG_IG_TAIL : bond.stroke == BG_IG_TAIL ? BG_IG_HEAD : 0};
    bg_ig_add_bond(M(b), bond);
  }
  free(flip);
  return rc;
}

/* A submodel's params are its parameters (an instance's label passes $N). */
static void params_to_signature(build *b) {
  bg_ig_model *m = M(b);
  if (!m->nparams) return;
  bg_strbuf sig = {0};
  for (int i = 0; i < m->nparams; i++) {
    bg_sb_printf(&sig, "%s%s = %s", i ? ", " : "(", m->params[i].name, m->params[i].value);
    if (m->params[i].desc) bg_sb_printf(&sig, " \"%s\"", m->params[i].desc);
  }
  bg_sb_putc(&sig, ')');
  m->params_sig = bg_arena_strdup(A(b), sig.s);
  bg_sb_free(&sig);
  m->nparams = 0;
}

static void simulate_statement(build *b) {
  const bg_mtt_row *last = bg_mtt_find(&b->r->simpar.rows, "LAST");
  const bg_mtt_row *dt = bg_mtt_find(&b->r->simpar.rows, "DT");
  if (!last) return;
  const char *s = dt ? bg_ig_printf(b->r->g, "simulate t_end = %s, dt = %s", last->f[1], dt->f[1])
                     : bg_ig_printf(b->r->g, "simulate t_end = %s", last->f[1]);
  bg_ig_add_extra(M(b), b->r->simpar.file, last->line, s);
}

static int build_sys(reader *r, sysrec *sr, const char *key, int root) {
  for (int i = 0; !root && i < sr->nvar; i++)
    if (!strcmp(sr->keys[i], key)) return sr->mis[i];
  if (sr->building) {
    bg_diag_error(r->dg, (bg_srcloc){1, 1, sr->s.file}, "MTT model: the subsystem %s contains itself",
                  sr->s.type);
    return -1;
  }
  int mi = 0;
  if (!root) { /* a name no other model has */
    const char *name = bg_ig_name(r->g, NULL, sr->s.type);
    for (int k = 2;; k++) {
      int used = 0;
      for (int i = 0; i < r->g->nmodels; i++) used |= !strcmp(r->g->models[i].name, name);
      if (!used) break;
      name = bg_ig_printf(r->g, "%s_%d", bg_ig_name(r->g, NULL, sr->s.type), k);
    }
    mi = bg_ig_add_model(r->g, name, 1);
    r->g->models[mi].file = sr->s.file;
    bg_ig_add_note(r->g, &r->g->models[mi], 1, "MTT subsystem %s%s%s%s", sr->s.type,
                   *key ? " (port directions " : "", key, *key ? ": i in, o out)" : "");
  }
  sr->building = 1;
  build b = {r, sr, mi, root, NULL, NULL, 0, 0, {0}, 0, NULL, NULL, NULL, NULL};
  const bg_mtt_sys *s = &sr->s;
  b.end_node = bg_xmalloc(sizeof *b.end_node * (size_t)(2 * s->nb + 1));
  b.end_sfx = bg_xmalloc(sizeof *b.end_sfx * (size_t)(2 * s->nb + 1));
  b.comp_node = bg_xmalloc(sizeof *b.comp_node * (size_t)(s->nc + 1));
  b.free_stroke = calloc((size_t)s->nb + 1, 1);
  if (!b.free_stroke) BG_FATAL("out of memory");
  int *junction_bonds = bg_xmalloc(sizeof *junction_bonds * (size_t)(s->nc + 1));
  for (int i = 0; i < 2 * s->nb; i++) b.end_node[i] = -1, b.end_sfx[i] = "";
  int rc = 0;
  for (int i = 0; i < s->nc; i++) { /* junctions first: detectors name them */
    const bg_mtt_comp *c = &s->c[i];
    b.comp_node[i] = -1, junction_bonds[i] = c->nbonds;
    if (strcmp(c->type, "0") && strcmp(c->type, "1")) continue;
    int node = add_node(&b, c, comp_name(&b, c), c->type, NULL, NULL);
    b.comp_node[i] = node;
    for (int j = 0; j < s->nb; j++)
      for (int k = 0; k < 2; k++)
        if (s->b[j].comp[k] == i) set_end(&b, j, k, node, NULL);
  }
  for (int i = 0; i < s->nnotes; i++) bg_ig_add_note(r->g, M(&b), 0, "%s", s->notes[i]);
  for (int i = 0; i < s->nc; i++)
    if (component(&b, i, junction_bonds)) rc = -1;
  if (!rc) rc = bonds(&b, root ? NULL : key);
  if (root) simulate_statement(&b);
  else { /* $N: the parameters an instance's label passes */
    for (int i = 0; i < s->lbl.aliases.n; i++) {
      const bg_mtt_row *a = &s->lbl.aliases.v[i];
      if (a->f[0][0] != '$' || !isdigit((unsigned char)a->f[0][1])) continue;
      int k = atoi(a->f[0] + 1);
      if (k < 1 || k > MAX_PORTS || !is_name(a->f[1])) continue;
      const char *name = use_symbol(&b, a->f[1]);
      if (k > sr->npos) {
        sr->pos = bg_xrealloc(sr->pos, sizeof *sr->pos * (size_t)k);
        for (int j = sr->npos; j < k; j++) sr->pos[j] = NULL;
        sr->npos = k;
      }
      sr->pos[k - 1] = name;
    }
    params_to_signature(&b);
  }
  free(b.end_node), free(b.end_sfx), free(b.comp_node), free(b.free_stroke), free(junction_bonds), free(b.sym), free(b.sym_bg);
  bg_strindex_free(&b.sym_idx);
  sr->building = 0;
  if (rc) return -1;
  if (!root) {
    sr->keys = bg_xrealloc(sr->keys, sizeof *sr->keys * (size_t)(sr->nvar + 1));
    sr->mis = bg_xrealloc(sr->mis, sizeof *sr->mis * (size_t)(sr->nvar + 1));
    sr->keys[sr->nvar] = bg_arena_strdup(&r->g->arena, key);
    sr->mis[sr->nvar++] = mi;
  }
  return mi;
}

/* The system's name and folder from its drawing's path: DIR/NAME_abg.fig
 * (or DIR/NAME.fig). */
static void split_path(bg_arena *a, const char *path, const char **dir, const char **type) {
  const char *slash = strrchr(path, '/');
  *dir = slash ? bg_arena_strndup(a, path, (size_t)(slash - path)) : "";
  const char *base = slash ? slash + 1 : path;
  size_t n = strlen(base);
  if (n > 8 && !strcmp(base + n - 8, "_abg.fig")) n -= 8;
  else if (n > 4 && !strcmp(base + n - 4, ".fig")) n -= 4;
  *type = bg_arena_strndup(a, base, n);
}

int bg_mtt_read(const char *path, const char *src, size_t len, bg_ig *g, bg_diags *dg) {
  reader r = {g, dg, NULL, 0, {0}, {0}, {0}, NULL, 0};
  sysrec *root = calloc(1, sizeof *root);
  if (!root) BG_FATAL("out of memory");
  split_path(&g->arena, path ? path : "model", &root->s.dir, &root->s.type);
  r.root_type = root->s.type;
  r.sys = bg_xmalloc(sizeof *r.sys);
  r.sys[r.nsys++] = root;
  int rc = load_sys(&r, root, path, src, len, 0);
  const char *kinds[3] = {"_numpar.txt", "_input.txt", "_simpar.txt"};
  bg_mtt_assign *files[3] = {&r.numpar, &r.input, &r.simpar};
  for (int i = 0; i < 3; i++) {
    char *p = join(root->s.dir, root->s.type, kinds[i], "");
    if (bg_mtt_read_assign(p, &g->arena, dg, files[i])) rc = -1;
    free(p);
  }
  if (!rc) {
    int mi = bg_ig_add_model(g, bg_ig_name(g, NULL, root->s.type), 1);
    g->models[mi].title = root->s.lbl.summary;
    if (root->s.lbl.summary) g->models[mi].line = root->s.lbl.summary_line, g->models[mi].file = root->s.lbl.file;
    static const char *const what[3] = {"numpar", "input", "simpar"};
    for (int i = 0; i < 3; i++)
      if (files[i]->skipped)
        bg_ig_add_note(g, &g->models[mi], 0,
                       "%s_%s.txt: %d line%s that %s not 'name = value' (from line %d) not read",
                       root->s.type, what[i], files[i]->skipped, files[i]->skipped == 1 ? "" : "s",
                       files[i]->skipped == 1 ? "is" : "are", files[i]->skipped_line);
    if (build_sys(&r, root, "", 1) < 0) rc = -1;
  }
  for (int i = 0; i < r.nsys; i++) {
    sysrec *sr = r.sys[i];
    free(sr->s.c), free(sr->s.b), free(sr->s.notes), free(sr->keys), free(sr->mis), free(sr->pos);
    bg_mtt_rows_free(&sr->s.lbl.rows), bg_mtt_rows_free(&sr->s.lbl.aliases);
    free(sr);
  }
  for (int i = 0; i < 3; i++) bg_mtt_rows_free(&files[i]->rows);
  free(r.sys);
  return rc;
}
