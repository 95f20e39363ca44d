/* SPDX-License-Identifier: BSD-3-Clause */
/* Modelica export (docs/export.md): one model per file with the params as
 * parameters, the stores' states with start values, every bond variable as a
 * Real, and the bond graph's equations unsorted (each element's relation as
 * bgdraw derived it, the junction balances, der() for the states), so that a
 * Modelica tool does its own sorting and index reduction. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "export/export_int.h"

/* A name as a Modelica identifier: '.' and other characters made '_', a
 * keyword, predefined type or built-in operator (time, der, Real, sin) gets
 * a trailing '_' (export_names.c). */
static void mo_ident(const char *name, char *buf, size_t n) { bg_export_ident_in(bg_reserved_modelica, name, buf, n); }

typedef struct mo { const bg_eqsys *s; bg_strbuf *o; } mo;

static void put_ident(mo *M, const char *name) {
  char id[300];
  mo_ident(name, id, sizeof id);
  bg_sb_puts(M->o, id);
}

static void put_sig(mo *M, int sig) {
  bg_arena tmp = {0};
  put_ident(M, bg_eqs_signame(M->s, sig, &tmp));
  bg_arena_free(&tmp);
}

static void put_num(mo *M, double c) {
  if (c < 0) bg_sb_putc(M->o, '('), bg_sb_num(M->o, c), bg_sb_putc(M->o, ')');
  else bg_sb_num(M->o, c);
}

static void x_expr(mo *M, int x);

static void x_args(mo *M, const bg_xnode *n, const char *sep) {
  for (int k = 0; k < n->nargs; k++) {
    if (k) bg_sb_puts(M->o, sep);
    x_expr(M, n->arg[k]);
  }
}

/* A 0/1 number from a Boolean: bgdraw's comparisons and logic are numbers. */
static void boolean(mo *M, const bg_xnode *n, const char *op) {
  bg_sb_puts(M->o, "(if ");
  if (n->op == BG_X_NOT) bg_sb_puts(M->o, "("), x_expr(M, n->arg[0]), bg_sb_puts(M->o, ") == 0");
  else if (n->op == BG_X_AND || n->op == BG_X_OR) {
    bg_sb_puts(M->o, "("), x_expr(M, n->arg[0]), bg_sb_printf(M->o, ") <> 0 %s (", op);
    x_expr(M, n->arg[1]), bg_sb_puts(M->o, ") <> 0");
  } else bg_sb_puts(M->o, "("), x_expr(M, n->arg[0]), bg_sb_printf(M->o, ") %s (", op), x_expr(M, n->arg[1]), bg_sb_puts(M->o, ")");
  bg_sb_puts(M->o, " then 1 else 0)");
}

static void call(mo *M, const bg_xnode *n) {
  const bg_model *m = M->s->m;
  const char *a = NULL;
  switch (n->ref) {
  case BG_FN_POW: bg_sb_puts(M->o, "("), x_expr(M, n->arg[0]), bg_sb_puts(M->o, ")^("), x_expr(M, n->arg[1]), bg_sb_puts(M->o, ")"); return;
  case BG_FN_IF: a = "(if (%0) <> 0 then %1 else %2)"; break;
  case BG_FN_STEP: a = "(if %0 < 0 then 0 else 1)"; break;
  case BG_FN_RAMP: a = "(if %0 < 0 then 0 else %0)"; break;
  case BG_FN_PULSE: a = "(if %0 >= 0 and %0 < %1 then 1 else 0)"; break;
  case BG_FN_SAT: a = "(if %0 < %1 then %1 elseif %0 > %2 then %2 else %0)"; break;
  case BG_FN_HYST: a = "(if %0 >= %2 then 1 else 0)"; break; /* as it starts: refused (bg_export_refusal) */
  case BG_FN_STICK: a = "(if %0 == 0 and abs(%1) <= %2 then 1 else 0)"; break;
  default:
    bg_sb_printf(M->o, "%s(", bg_func_name(n->ref));
    x_args(M, n, ", ");
    bg_sb_puts(M->o, ")");
    return;
  }
  (void)m;
  for (const char *p = a; *p; p++) {
    if (*p == '%' && p[1] >= '0' && p[1] <= '2') {
      bg_sb_putc(M->o, '('), x_expr(M, n->arg[p[1] - '0']), bg_sb_putc(M->o, ')');
      p++;
    } else bg_sb_putc(M->o, *p);
  }
}

static void x_expr(mo *M, int x) {
  const bg_model *m = M->s->m;
  const bg_xnode *n = &m->xnode[x];
  static const char *bin[] = {[BG_X_ADD] = " + ", [BG_X_SUB] = " - ", [BG_X_MUL] = "*", [BG_X_DIV] = "/"};
  char buf[300];
  switch (n->op) {
  case BG_X_NUM: put_num(M, n->num); return;
  case BG_X_TIME: bg_sb_puts(M->o, "time"); return;
  case BG_X_PARAM: put_ident(M, m->param_name[n->ref]); return;
  case BG_X_INPUT: put_ident(M, m->input_name[n->ref]); return;
  case BG_X_STATE: put_ident(M, m->state_name[n->ref]); return;
  case BG_X_EFFORT: put_sig(M, 2 * n->ref); return;
  case BG_X_FLOW: put_sig(M, 2 * n->ref + 1); return;
  case BG_X_STORE:
    snprintf(buf, sizeof buf, "%s.%s", m->elem_name[n->ref], m->elem_kind[n->ref] == BG_ELEM_I ? "p" : "q");
    put_ident(M, buf);
    return;
  case BG_X_NEG: bg_sb_puts(M->o, "-("), x_expr(M, n->arg[0]), bg_sb_puts(M->o, ")"); return;
  case BG_X_POW: bg_sb_puts(M->o, "("), x_expr(M, n->arg[0]), bg_sb_puts(M->o, ")^("), x_expr(M, n->arg[1]), bg_sb_puts(M->o, ")"); return;
  case BG_X_ADD: case BG_X_SUB: case BG_X_MUL: case BG_X_DIV:
    bg_sb_puts(M->o, "("), x_expr(M, n->arg[0]), bg_sb_puts(M->o, bin[n->op]), x_expr(M, n->arg[1]), bg_sb_puts(M->o, ")");
    return;
  case BG_X_LT: boolean(M, n, "<"); return;
  case BG_X_LE: boolean(M, n, "<="); return;
  case BG_X_GT: boolean(M, n, ">"); return;
  case BG_X_GE: boolean(M, n, ">="); return;
  case BG_X_EQ: boolean(M, n, "=="); return;
  case BG_X_NE: boolean(M, n, "<>"); return;
  case BG_X_AND: boolean(M, n, "and"); return;
  case BG_X_OR: boolean(M, n, "or"); return;
  case BG_X_NOT: boolean(M, n, "not"); return;
  case BG_X_CALL: call(M, n); return;
  case BG_X_TABLE:
    bg_sb_printf(M->o, "bg_table(");
    x_expr(M, n->arg[0]);
    bg_sb_printf(M->o, ", tab%d_x, tab%d_y)", n->ref + 1, n->ref + 1);
    return;
  default: bg_sb_puts(M->o, "0"); return;
  }
}

/* An equation tree (eqsys_int.h) as a Modelica expression. */
static void eq_expr(mo *M, int nd) {
  const bg_eqsys *s = M->s;
  const eq_node *n = &s->node[nd];
  switch (n->kind) {
  case EQ_NUM: put_num(M, n->c); return;
  case EQ_X: x_expr(M, n->a); return;
  case EQ_SIG: put_sig(M, n->a); return;
  case EQ_Y: put_ident(M, s->uname[n->a]); return;
  case EQ_YP: bg_sb_puts(M->o, "der("), put_ident(M, s->uname[n->a]), bg_sb_puts(M->o, ")"); return;
  case EQ_MUL: case EQ_DIV:
    bg_sb_puts(M->o, "("), eq_expr(M, n->a), bg_sb_puts(M->o, n->kind == EQ_MUL ? ")*(" : ")/("), eq_expr(M, n->b);
    bg_sb_puts(M->o, ")");
    return;
  default: /* EQ_LIN */
    if (!n->b) { bg_sb_puts(M->o, "0"); return; }
    bg_sb_puts(M->o, "(");
    for (int k = 0; k < n->b; k++) {
      double c = s->lin_coef[n->a + k];
      if (k) bg_sb_puts(M->o, c < 0 ? " - " : " + ");
      else if (c < 0) bg_sb_puts(M->o, "-");
      if (fabs(c) != 1) put_num(M, fabs(c)), bg_sb_puts(M->o, "*");
      eq_expr(M, s->lin_node[n->a + k]);
    }
    bg_sb_puts(M->o, ")");
    return;
  }
}

static const char *table_fn =
    "protected\n  function bg_table \"linear interpolation, clamped at the ends (bgdraw's table)\"\n"
    "    input Real x;\n    input Real X[:];\n    input Real Y[size(X, 1)];\n    output Real y;\n"
    "  protected\n    Integer lo;\n    Integer hi;\n    Integer mid;\n  algorithm\n"
    "    if x <= X[1] then\n      y := Y[1];\n    elseif x >= X[end] then\n      y := Y[end];\n"
    "    else\n      lo := 1;\n      hi := size(X, 1);\n      while hi - lo > 1 loop\n"
    "        mid := div(lo + hi, 2);\n        if X[mid] <= x then\n          lo := mid;\n"
    "        else\n          hi := mid;\n        end if;\n      end while;\n"
    "      y := Y[lo] + (x - X[lo])/(X[hi] - X[lo])*(Y[hi] - Y[lo]);\n    end if;\n  end bg_table;\n";

static void declarations(mo *M, const double *y0) {
  const bg_eqsys *s = M->s;
  const bg_model *m = s->m;
  bg_strbuf *o = M->o;
  for (int k = 0; k < m->nparam; k++) {
    bg_sb_puts(o, "  parameter Real "), put_ident(M, m->param_name[k]), bg_sb_puts(o, " = ");
    if (bg_eqsys_param_is_derived(s, k)) x_expr(M, m->param_expr[k]);
    else bg_sb_num(o, m->param_value[k]);
    char id[300];
    mo_ident(m->param_name[k], id, sizeof id);
    if (strcmp(id, m->param_name[k])) bg_sb_printf(o, " \"bgdraw param %s\"", m->param_name[k]); /* renamed */
    bg_sb_puts(o, ";\n");
  }
  for (int t = 0; t < m->ntable; t++)
    for (int a = 0; a < 2; a++) {
      bg_sb_printf(o, "  parameter Real tab%d_%c[%d] = {", t + 1, a ? 'y' : 'x', m->table_n[t]);
      for (int k = 0; k < m->table_n[t]; k++) {
        if (k) bg_sb_puts(o, ", ");
        put_num(M, (a ? m->table_y : m->table_x)[m->table_adr[t] + k]);
      }
      bg_sb_puts(o, "};\n");
    }
  for (int i = 0; i < s->n; i++) {
    if (s->u_sig[i] >= 0) continue; /* an algebraic unknown: declared as its bond variable */
    bg_sb_puts(o, "  Real "), put_ident(M, s->uname[i]), bg_sb_puts(o, "(start = ");
    int root = s->u_elem[i] >= 0 ? m->elem_init[s->u_elem[i]] : s->u_state[i] >= 0 ? m->state_init[s->u_state[i]] : -1;
    if (i < s->nint && root >= 0) x_expr(M, root);
    else bg_sb_num(o, y0[i]);
    bg_sb_printf(o, ", fixed = %s);\n", i < s->nint ? "true" : "false");
  }
  for (int k = 0; k < m->ninput; k++) bg_sb_puts(o, "  Real "), put_ident(M, m->input_name[k]), bg_sb_puts(o, ";\n");
  for (int v = 0; v < s->nsig; v++) {
    bg_sb_puts(o, "  Real "), put_sig(M, v);
    if (s->sig_torn[v]) bg_sb_puts(o, "(start = "), bg_sb_num(o, y0[s->sig_z[v]]), bg_sb_puts(o, ")");
    bg_sb_printf(o, " \"%s %d\";\n", v & 1 ? "flow of bond" : "effort of bond", m->bond_num[v / 2]);
  }
}

static void equations(mo *M) {
  const bg_eqsys *s = M->s;
  const bg_model *m = s->m;
  bg_strbuf *o = M->o;
  bg_sb_puts(o, "equation\n");
  for (int k = 0; k < m->ninput; k++)
    bg_sb_puts(o, "  "), put_ident(M, m->input_name[k]), bg_sb_puts(o, " = "), x_expr(M, m->input_expr[k]), bg_sb_puts(o, ";\n");
  for (int v = 0; v < s->nsig; v++) {
    if (s->sig_torn[v] || s->sig_form[v] != EQF_EXPLICIT) continue;
    bg_sb_puts(o, "  "), put_sig(M, v), bg_sb_puts(o, " = "), eq_expr(M, s->sig_root[v]);
    bg_sb_printf(o, "; // %s of %s\n", s->sig_what[v], m->elem_name[s->sig_elem[v]]);
  }
  for (int i = 0; i < s->n; i++) {
    bg_sb_puts(o, "  ");
    if (s->row_kind[i] == 0) bg_sb_puts(o, "der("), put_ident(M, s->uname[i]), bg_sb_puts(o, ") = ");
    else bg_sb_puts(o, "0 = ");
    eq_expr(M, s->row_root[i]);
    bg_sb_puts(o, ";\n");
  }
}

void bg_export_modelica(const bg_eqsys *s, bg_strbuf *o) {
  const bg_model *m = s->m;
  mo M = {s, o};
  char name[300];
  mo_ident(m->name && *m->name ? m->name : "model", name, sizeof name);
  double *y0 = bg_xcalloc((size_t)s->n + 1, sizeof(double));
  bg_eqsys_initial(s, y0);
  bg_sb_printf(o, "// Generated by bgdraw from model %s (docs/export.md): the bond graph's equations,\n"
                  "// unsorted; the Modelica tool sorts them and reduces the index where needed.\n"
                  "model %s", m->name, name);
  if (m->title) bg_sb_puts(o, " "), bg_sb_json_str(o, m->title);
  bg_sb_puts(o, "\n");
  declarations(&M, y0);
  if (m->ntable) bg_sb_puts(o, table_fn);
  equations(&M);
  if (m->sim.present) {
    bg_sb_puts(o, "  annotation(experiment(StartTime = "), bg_sb_num(o, m->sim.t0);
    bg_sb_puts(o, ", StopTime = "), bg_sb_num(o, m->sim.t_end);
    if (m->sim.dt > 0) bg_sb_puts(o, ", Interval = "), bg_sb_num(o, m->sim.dt);
    bg_sb_puts(o, "));\n");
  }
  bg_sb_printf(o, "end %s;\n", name);
  free(y0);
}
