/* SPDX-License-Identifier: BSD-3-Clause */
/* The variables of index reduction's work (indexred_int.h), shared by the
 * algorithm (indexred.c) and the builder of the reduced system
 * (indexred_build.c), which indexred.c calls: a variable as a symbolic leaf,
 * and the variables an expression reads. */
#include <stdlib.h>

#include "equations/indexred_int.h"

int ir_var_leaf(ir_work *W, int v) { return bg_sym_leaf(W->S, SYM_Y, v); }

void ir_expr_vars(ir_work *W, int e, bg_ivec *out) {
  bg_sym *S = W->S;
  int nn = S->nnode;
  unsigned char *mark = bg_xcalloc((size_t)nn + 1, 1);
  for (int id = 0; id < nn; id++)
    mark[id] = S->node[id].kind == SYM_Y && S->node[id].n == 0 && S->node[id].ref < W->nv;
  int cnt = bg_sym_leaves(S, e, mark, nn, NULL, 0);
  int *ids = bg_xmalloc((size_t)(cnt + 1) * sizeof(int));
  bg_sym_leaves(S, e, mark, nn, ids, cnt);
  for (int k = 0; k < cnt; k++) bg_ivec_push(out, S->node[ids[k]].ref);
  free(ids), free(mark);
}
