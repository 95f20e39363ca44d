/* SPDX-License-Identifier: BSD-3-Clause */
/* The transformations' driver: the names, the header of the new text, and
 * the check of the new model (parsed, compiled, given causality and
 * analysed) before it is handed back; docs/transform.md. The look-ups and
 * edits the transformations share are in tx_edit.c. */
#include <stdlib.h>
#include <string.h>

#include "analysis/analysis.h"
#include "causality/causality.h"
#include "lang/lang.h"
#include "transform/tx_int.h"

static const struct {
  const char *name;
  int (*run)(tx_ctx *);
} transforms[] = {
    {"merge-stores", tx_merge_stores},
    {"parasitic", tx_parasitic},
    {"relax-junction", tx_relax_junction},
};
enum { NTRANSFORM = sizeof transforms / sizeof *transforms };

int bg_transform_known(const char *name) {
  for (int i = 0; i < NTRANSFORM; i++)
    if (!strcmp(name, transforms[i].name)) return 1;
  return 0;
}

const char *bg_transform_names(void) { return "merge-stores, parasitic, relax-junction"; }

/* The header comment: the transformation, the source, and why, wrapped. */
static void write_header(tx_ctx *c) {
  bg_strbuf *h = &c->doc.head;
  const char *base = strrchr(c->in->path, '/');
  bg_sb_printf(h, "# Transformed by bgdraw --transform %s from %s.\n", c->in->name,
               base ? base + 1 : c->in->path);
  const char *s = bg_sb_str(&c->why);
  while (*s) {
    while (*s == ' ') s++;
    int n = (int)strlen(s), cut = n;
    if (n > 76) {
      cut = 76;
      while (cut > 0 && s[cut] != ' ') cut--;
      if (cut == 0) cut = n;
    }
    bg_sb_puts(h, "# ");
    bg_sb_putn(h, s, (size_t)cut);
    bg_sb_putc(h, '\n');
    s += cut;
  }
}

/* The new text compiled and analysed into out. */
static int check_result(tx_ctx *c, bg_transform_result *out, char **why) {
  return tx_compile(c, out->text, &out->run, why);
}

int bg_transform_apply(const bg_transform_input *in, bg_transform_result *out, char **why) {
  memset(out, 0, sizeof *out);
  *why = NULL;
  int k = 0;
  while (k < NTRANSFORM && strcmp(in->name, transforms[k].name)) k++;
  if (k == NTRANSFORM) BG_FATAL("unknown transformation %s", in->name);
  if (in->ast->has_components) {
    *why = strdup("the model has submodels: transformations edit models without components "
                  "(version 1) only");
    return -1;
  }
  tx_ctx c;
  memset(&c, 0, sizeof c);
  c.in = in;
  c.m = in->model;
  c.a = in->analysis;
  c.method = -1;
  for (int b = 0; b < c.m->nbond; b++)
    if (c.m->bond_num[b] >= c.next_bond) c.next_bond = c.m->bond_num[b] + 1;
  tx_doc_init(&c.doc, in->src, in->srclen);
  int rc = transforms[k].run(&c);
  if (rc == 0) {
    write_header(&c);
    out->text = tx_doc_text(&c.doc);
    out->summary = strdup(bg_sb_str(&c.why));
    rc = check_result(&c, out, why);
  } else {
    *why = strdup(bg_sb_str(&c.problem));
  }
  tx_doc_free(&c.doc);
  bg_sb_free(&c.why);
  bg_sb_free(&c.problem);
  if (rc) bg_transform_result_free(out);
  return rc;
}

void bg_transform_result_free(bg_transform_result *r) {
  free(r->text);
  free(r->summary);
  bg_run_free(r->run);
  memset(r, 0, sizeof *r);
}
