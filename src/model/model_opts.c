/* SPDX-License-Identifier: BSD-3-Clause */
/* Statement options (model_int.h), shared by elements and statements
 * (model_stmt.c) and fields (model_field.c): unknown and repeated keys,
 * strings, colours, words from a list, numbers, initial values, positions. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "model/expr.h"
#include "model/model_int.h"

/* Reports unknown and repeated option keys; `valid` is "a, b, c". */
void bg_build_check_options(bg_build *b, const bg_ast_stmt *s, const char *valid, const char *whose) {
  for (int i = 0; i < s->nopts; i++) {
    const char *key = s->opts[i].key;
    size_t n = strlen(key);
    const char *p = valid;
    int found = 0;
    while ((p = strstr(p, key)) != NULL && !found) {
      found = (p == valid || p[-1] == ' ') && (p[n] == ',' || p[n] == '\0');
      p += n;
    }
    if (!found) {
      char best[32] = "";
      int bestd = 3;
      for (const char *q = valid; *q;) { /* the nearest valid option: tend -> t_end */
        size_t len = strcspn(q, ",");
        char cand[32];
        snprintf(cand, sizeof cand, "%.*s", (int)len, q);
        int d = bg_edit_distance(key, cand);
        if (d < bestd) bestd = d, snprintf(best, sizeof best, "%s", cand);
        q += len;
        while (*q == ',' || *q == ' ') q++;
      }
      if (best[0])
        bg_diag_error(b->dg, s->opts[i].loc, "unknown option '%s' for %s (did you mean '%s'? "
                      "valid: %s)", key, whose, best, valid);
      else
        bg_diag_error(b->dg, s->opts[i].loc, "unknown option '%s' for %s (valid: %s)", key, whose,
                      valid);
      continue;
    }
    for (int j = 0; j < i; j++)
      if (strcmp(s->opts[j].key, key) == 0) {
        bg_diag_error(b->dg, s->opts[i].loc, "option '%s' given twice (first at column %d)", key,
                      s->opts[j].loc.col);
        break;
      }
  }
}

const bg_ast_option *bg_build_find_opt(const bg_ast_stmt *s, const char *key) {
  for (int i = 0; i < s->nopts; i++)
    if (strcmp(s->opts[i].key, key) == 0) return &s->opts[i];
  return NULL;
}

/* A string option ("..."); NULL if absent or wrong (reported). */
const char *bg_build_string_opt(bg_build *b, const bg_ast_stmt *s, const char *key) {
  const bg_ast_option *o = bg_build_find_opt(s, key);
  if (!o) return NULL;
  if (o->value->kind != BG_EX_STR) {
    bg_diag_error(b->dg, o->value->loc, "option '%s' needs a string in quotes, e.g. %s = \"...\"",
                  key, key);
    return NULL;
  }
  return bg_build_strdup(b, o->value->str);
}

static int is_hex(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

const char *bg_build_color_opt(bg_build *b, const bg_ast_stmt *s) {
  const char *c = bg_build_string_opt(b, s, "color");
  if (!c) return NULL;
  int ok = strlen(c) == 7 && c[0] == '#';
  for (int i = 1; ok && i < 7; i++) ok = is_hex(c[i]);
  if (!ok) {
    bg_diag_error(b->dg, bg_build_find_opt(s, "color")->value->loc,
                  "color must be \"#rrggbb\" (6 hex digits), not \"%s\"", c);
    return NULL;
  }
  return c;
}

/* A word option (a name or a string) that must be one of `valid` ("a, b"). */
const char *bg_build_word_opt(bg_build *b, const bg_ast_stmt *s, const char *key, const char *valid) {
  const bg_ast_option *o = bg_build_find_opt(s, key);
  if (!o) return NULL;
  const bg_expr *v = o->value;
  if (v->kind == BG_EX_NAME || v->kind == BG_EX_STR) {
    const char *p = valid;
    size_t n = strlen(v->str);
    while (n && (p = strstr(p, v->str)) != NULL) {
      if ((p == valid || p[-1] == ' ') && (p[n] == ',' || p[n] == '\0'))
        return bg_build_strdup(b, v->str);
      p += n;
    }
  }
  bg_diag_error(b->dg, v->loc, "invalid %s '%s' (valid: %s)", key, v->text, valid);
  return NULL;
}

/* A numeric option: a constant expression of params; `def` when absent. */
double bg_build_num_opt(bg_build *b, const bg_ast_stmt *s, const char *key, double def) {
  const bg_ast_option *o = bg_build_find_opt(s, key);
  if (!o) return def;
  char what[96];
  snprintf(what, sizeof what, "option '%s' (use numbers, pi and params)", key);
  return bg_build_const(b, o->value, what);
}

/* An initial value (q0, p0, init): root xnode of a constant expression, -1 if absent. */
int bg_build_init_opt(bg_build *b, const bg_ast_stmt *s, const char *key) {
  const bg_ast_option *o = bg_build_find_opt(s, key);
  return o ? bg_build_init_expr(b, o->value) : -1;
}

/* One coordinate of `at`: finite and within BG_POSITION_MAX points, so the
 * layout and the drawing never see NaN, infinities or absurd sizes. */
static double position(bg_build *b, const bg_expr *x) {
  int nerr = b->dg->nerrors;
  double v = bg_build_const(b, x, "a position (use numbers and params)");
  if (b->dg->nerrors == nerr && !(fabs(v) <= BG_POSITION_MAX)) {
    char val[32];
    snprintf(val, sizeof val, isnan(v) ? "NaN" : "%g", v);
    bg_diag_error(b->dg, x->loc, "a position must be a finite number of points from -%.0f to "
                  "%.0f, not %s", BG_POSITION_MAX, BG_POSITION_MAX, val);
    return 0;
  }
  return v;
}

void bg_build_at_opt(bg_build *b, int e, const bg_ast_stmt *s) {
  const bg_ast_option *o = bg_build_find_opt(s, "at");
  if (!o) return;
  if (o->value->kind != BG_EX_TUPLE || o->value->nargs != 2) {
    bg_diag_error(b->dg, o->value->loc, "option 'at' needs a position (X, Y)");
    return;
  }
  b->m->elem_has_at[e] = 1;
  b->m->elem_at_x[e] = position(b, o->value->args[0]);
  b->m->elem_at_y[e] = position(b, o->value->args[1]);
}

/* A constant expression of params (an initial value) as xnodes. */
int bg_build_init_expr(bg_build *b, const bg_expr *x) {
  int allow = b->allow, elem = b->elem, law = b->law_elem;
  b->allow = 0;
  b->elem = b->law_elem = -1;
  b->what = "an initial value (use numbers, pi and params)";
  int root = bg_build_expr(b, x);
  b->allow = allow;
  b->elem = elem;
  b->law_elem = law;
  return root;
}
