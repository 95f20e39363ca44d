/* SPDX-License-Identifier: BSD-3-Clause */
/* The imported graph (import_int.h): models of nodes, bonds and params that
 * the readers fill, bond directions fixed from what each end demands, and
 * the .bg text printed with a map from its lines to the source's. */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/strbuf.h"
#include "import/import_int.h"

#define GROW(arr, n, cap)                                              \
  do {                                                                 \
    if ((n) == (cap)) {                                                \
      (cap) = (cap) ? 2 * (cap) : 8;                                   \
      (arr) = bg_xrealloc((arr), (size_t)(cap) * sizeof *(arr));       \
    }                                                                  \
  } while (0)

int bg_ig_add_model(bg_ig *g, const char *name, int line) {
  GROW(g->models, g->nmodels, g->capmodels);
  bg_ig_model *m = &g->models[g->nmodels];
  memset(m, 0, sizeof *m);
  m->name = name;
  m->line = line;
  return g->nmodels++;
}

int bg_ig_add_node(bg_ig_model *m, bg_ig_node n) {
  GROW(m->nodes, m->nnodes, m->capnodes);
  m->nodes[m->nnodes] = n;
  return m->nnodes++;
}

int bg_ig_add_bond(bg_ig_model *m, bg_ig_bond b) {
  GROW(m->bonds, m->nbonds, m->capbonds);
  m->bonds[m->nbonds] = b;
  return m->nbonds++;
}

void bg_ig_add_param(bg_ig_model *m, bg_ig_param p) {
  GROW(m->params, m->nparams, m->capparams);
  m->params[m->nparams++] = p;
}

void bg_ig_add_extra(bg_ig_model *m, int file, int line, const char *text) {
  if (m->nextra == m->capextra) {
    m->capextra = m->capextra ? 2 * m->capextra : 8;
    m->extra = bg_xrealloc(m->extra, (size_t)m->capextra * sizeof *m->extra);
    m->extra_lines = bg_xrealloc(m->extra_lines, (size_t)m->capextra * sizeof *m->extra_lines);
    m->extra_files = bg_xrealloc(m->extra_files, (size_t)m->capextra * sizeof *m->extra_files);
  }
  m->extra[m->nextra] = text;
  m->extra_lines[m->nextra] = line;
  m->extra_files[m->nextra++] = file;
}

/* fmt's text in g's arena. */
static char *arena_vprintf(bg_ig *g, const char *fmt, va_list ap) {
  va_list ap2;
  va_copy(ap2, ap);
  int n = vsnprintf(NULL, 0, fmt, ap);
  char *s = bg_arena_alloc(&g->arena, (size_t)n + 1);
  vsnprintf(s, (size_t)n + 1, fmt, ap2);
  va_end(ap2);
  return s;
}

char *bg_ig_printf(bg_ig *g, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  char *s = arena_vprintf(g, fmt, ap);
  va_end(ap);
  return s;
}

void bg_ig_add_note(bg_ig *g, bg_ig_model *m, int line, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  char *s = arena_vprintf(g, fmt, ap);
  va_end(ap);
  if (m->nnotes == m->capnotes) {
    m->capnotes = m->capnotes ? 2 * m->capnotes : 8;
    m->notes = bg_xrealloc(m->notes, (size_t)m->capnotes * sizeof *m->notes);
    m->note_lines = bg_xrealloc(m->note_lines, (size_t)m->capnotes * sizeof *m->note_lines);
  }
  m->notes[m->nnotes] = s;
  m->note_lines[m->nnotes++] = line;
}

static int find_node(const bg_ig_model *m, const char *name) {
  for (int i = 0; i < m->nnodes; i++)
    if (!strcmp(m->nodes[i].name, name)) return i;
  return -1;
}

/* Names the .bg language gives a meaning of its own (keywords, t, pi, the
 * contextual words of submodels, bond variables e7/f7). */
static int taken_word(const char *s) {
  static const char *const words[] = {"model", "param", "input", "state", "bond", "simulate",
                                      "plot", "layout", "causality", "output", "linearise",
                                      "t", "pi", "submodel", "use", "port", "end"};
  for (size_t i = 0; i < sizeof words / sizeof *words; i++)
    if (!strcmp(s, words[i])) return 1;
  if ((s[0] == 'e' || s[0] == 'f') && s[1]) {
    const char *p = s + 1;
    while (isdigit((unsigned char)*p)) p++;
    if (!*p) return 1;
  }
  return 0;
}

static int name_used(const bg_ig_model *m, const char *s) {
  if (m && find_node(m, s) >= 0) return 1;
  for (int i = 0; m && i < m->nparams; i++)
    if (!strcmp(m->params[i].name, s)) return 1;
  return 0;
}

const char *bg_ig_name(bg_ig *g, const bg_ig_model *m, const char *name) {
  size_t n = strlen(name);
  char *s = bg_arena_alloc(&g->arena, n + 16);
  size_t k = 0;
  if (!n || isdigit((unsigned char)name[0])) s[k++] = '_';
  for (size_t i = 0; i < n; i++)
    s[k++] = isalnum((unsigned char)name[i]) || name[i] == '_' ? name[i] : '_';
  s[k] = 0;
  if (taken_word(s)) s[k++] = '_', s[k] = 0;
  if (!name_used(m, s)) return s;
  for (int i = 2;; i++) {
    snprintf(s + k, 16, "_%d", i);
    if (!name_used(m, s)) return s;
  }
}

void bg_ig_free(bg_ig *g) {
  for (int i = 0; i < g->nmodels; i++) {
    bg_ig_model *m = &g->models[i];
    free(m->nodes), free(m->bonds), free(m->params), free(m->notes), free(m->note_lines);
    free(m->extra), free(m->extra_lines), free(m->extra_files);
  }
  free(g->models);
  bg_arena_free(&g->arena);
  memset(g, 0, sizeof *g);
}

/* ------------------------------------------------------------ printing */
typedef struct {
  bg_strbuf sb;
  bg_ivec map;  /* source line of each printed line */
  bg_ivec fmap; /* and its source file (bg_diags index) */
} printer;

/* One line of text (no newline inside) from line `line` of source `file`. */
static void put_line(printer *p, int file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static void put_line(printer *p, int file, int line, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  bg_sb_vprintf(&p->sb, fmt, ap);
  va_end(ap);
  bg_sb_putc(&p->sb, '\n');
  bg_ivec_push(&p->map, line);
  bg_ivec_push(&p->fmap, file);
}

/* The value of an Sf: BondGraphTools' f is the flow out of the source, the
 * .bg value is the bond's flow, so it is negated when the bond points in. */
static const char *node_value(const bg_ig *g, const bg_ig_model *m, int i) {
  const bg_ig_node *n = &m->nodes[i];
  if (!n->value || !n->sf_value_neg_if_head) return n->value;
  for (int b = 0; b < m->nbonds; b++)
    if (m->bonds[b].b == i) {
      const char *v = n->value;
      if (v[0] == '-') return v + 1;
      return bg_ig_printf((bg_ig *)g, "-%s", v);
    }
  return n->value;
}

static const char *const arrows[] = {"->", "->|", "|->"}; /* by bg_ig_bond.stroke */

static void emit_model(const bg_ig *g, const bg_ig_model *m, int sub, printer *p) {
  const char *ind = sub ? "  " : "";
  for (int i = 0; i < m->nnotes; i++) put_line(p, m->file, m->note_lines[i], "%s# %s", ind, m->notes[i]);
  for (int i = 0; i < m->nparams; i++) {
    const bg_ig_param *q = &m->params[i];
    const char *kw = q->is_input ? "input" : "param";
    if (q->desc) put_line(p, q->file, q->line, "%s%s %s = %s \"%s\"", ind, kw, q->name, q->value, q->desc);
    else put_line(p, q->file, q->line, "%s%s %s = %s", ind, kw, q->name, q->value);
  }
  int nports = 0;
  bg_strbuf ports = {0};
  for (int i = 0; i < m->nnodes; i++)
    if (m->nodes[i].is_port) {
      bg_sb_printf(&ports, "%s%s", nports++ ? ", " : "", m->nodes[i].name);
    }
  if (nports) put_line(p, m->file, m->line, "%sport %s", ind, bg_sb_str(&ports));
  bg_sb_free(&ports);
  for (int i = 0; i < m->nnodes; i++) {
    const bg_ig_node *n = &m->nodes[i];
    if (n->is_port) continue;
    const char *v = node_value(g, m, i);
    bg_strbuf st = {0};
    bg_sb_printf(&st, "%s%-2s %s%s", ind, n->kind, n->name, n->sig ? n->sig : "");
    if (v) bg_sb_printf(&st, " = %s", v);
    if (n->law) bg_sb_printf(&st, " : %s", n->law);
    if (n->opts) bg_sb_printf(&st, "  [%s]", n->opts);
    if (n->comment) bg_sb_printf(&st, "  # %s", n->comment);
    put_line(p, n->file, n->line, "%s", bg_sb_str(&st));
    bg_sb_free(&st);
  }
  for (int i = 0; i < m->nbonds; i++) {
    const bg_ig_bond *b = &m->bonds[i];
    int s = b->stroke == BG_IG_HEAD ? 1 : b->stroke == BG_IG_TAIL ? 2 : 0;
    put_line(p, b->file, b->line, "%sbond %s%s %s %s%s", ind, m->nodes[b->a].name, b->pa, arrows[s],
             m->nodes[b->b].name, b->pb);
  }
  for (int i = 0; i < m->nextra; i++)
    put_line(p, m->extra_files ? m->extra_files[i] : m->file, m->extra_lines[i], "%s%s", ind, m->extra[i]);
}

void bg_ig_emit(const bg_ig *g, bg_import_result *out) {
  printer p = {{0}, {0}, {0}};
  bg_ivec_push(&p.map, 0); /* line 0 */
  bg_ivec_push(&p.fmap, 0);
  const bg_ig_model *root = &g->models[0];
  put_line(&p, 0, 0, "# %s, imported from %s (%s) by bgdraw; conventions in docs/import.md",
           root->name, g->source_path, g->format);
  if (root->title) put_line(&p, root->file, root->line, "model %s \"%s\"", root->name, root->title);
  else put_line(&p, root->file, root->line, "model %s", root->name);
  emit_model(g, root, 0, &p);
  for (int i = 1; i < g->nmodels; i++) {
    const bg_ig_model *m = &g->models[i];
    put_line(&p, 0, 0, "%s", "");
    put_line(&p, m->file, m->line, "submodel %s%s", m->name, m->params_sig ? m->params_sig : "");
    emit_model(g, m, 1, &p);
    put_line(&p, m->file, m->line, "end");
  }
  out->text = p.sb.s ? p.sb.s : strdup("");
  out->len = p.sb.len;
  out->line_of = p.map.v;
  out->file_of = p.fmap.v;
  out->nlines = p.map.n - 1;
}

/* ---------------------------------------------------------- directions */
int bg_ig_orient(bg_ig *g, int mi) {
  int added = 0;
  for (int i = 0, n = g->models[mi].nbonds; i < n; i++) {
    bg_ig_model *m = &g->models[mi];
    bg_ig_bond b = m->bonds[i];
    int a_head = b.ca == BG_IG_HEAD || b.cb == BG_IG_TAIL;
    int a_tail = b.ca == BG_IG_TAIL || b.cb == BG_IG_HEAD;
    if (!(a_head && a_tail)) {
      if (a_head) { /* b -> a */
        m->bonds[i] = (bg_ig_bond){b.b, b.a, b.pb, b.pa, b.cb, b.ca, b.line, b.file,
                                    b.stroke == BG_IG_HEAD ? BG_IG_TAIL : b.stroke == BG_IG_TAIL ? BG_IG_HEAD : 0};
      }
      continue;
    }
    /* Both ends want the bond pointing in (or both out): a 0-junction of two
     * bonds between them is the same equations (equal efforts, the flow into
     * one is the flow out of the other) with each end as it asks. */
    const char *zn = bg_ig_name(g, m, bg_ig_printf(g, "%s_%s", m->nodes[b.a].name, m->nodes[b.b].name));
    int z = bg_ig_add_node(m, (bg_ig_node){.name = zn, .kind = "0", .line = b.line,
                                           .comment = "joins two ends that both take power in, or both give it out"});
    int both_head = b.ca == BG_IG_HEAD;
    bg_ig_add_note(g, m, b.line, "bond %s%s %s%s: both ends %s power; joined through the 0-junction %s",
                   m->nodes[b.a].name, b.pa, m->nodes[b.b].name, b.pb,
                   both_head ? "take" : "give", zn);
    if (both_head) {
      m->bonds[i] = (bg_ig_bond){z, b.a, "", b.pa, BG_IG_FREE, BG_IG_FREE, b.line, b.file, 0};
      bg_ig_add_bond(m, (bg_ig_bond){z, b.b, "", b.pb, BG_IG_FREE, BG_IG_FREE, b.line, b.file, 0});
    } else {
      m->bonds[i] = (bg_ig_bond){b.a, z, b.pa, "", BG_IG_FREE, BG_IG_FREE, b.line, b.file, 0};
      bg_ig_add_bond(m, (bg_ig_bond){b.b, z, b.pb, "", BG_IG_FREE, BG_IG_FREE, b.line, b.file, 0});
    }
    added++;
  }
  return added;
}

int bg_ig_port_direction(const bg_ig_model *m, const char *port) {
  int p = find_node(m, port);
  if (p < 0 || !m->nodes[p].is_port) return -1;
  for (int i = 0; i < m->nbonds; i++) {
    if (m->bonds[i].a == p) return BG_IG_HEAD; /* power comes in at the port */
    if (m->bonds[i].b == p) return BG_IG_TAIL;
  }
  return BG_IG_FREE;
}
