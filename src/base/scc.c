/* SPDX-License-Identifier: BSD-3-Clause */
/* Tarjan's strongly connected components with an explicit stack of (vertex,
 * next edge) frames instead of recursion. */
#include "base/scc.h"

#include <stdlib.h>

#include "base/arena.h"

typedef struct scc_work {
  int *index, *low, *stk, *fv, *fpos;
  char *on;
  int idx, sp, fp;
} scc_work;

static void scc_visit(scc_work *W, int v) {
  W->index[v] = W->low[v] = W->idx++;
  W->stk[W->sp++] = v;
  W->on[v] = 1;
  W->fv[W->fp] = v;
  W->fpos[W->fp++] = 0;
}

int bg_scc(int nn, const int *adr, const int *deg, const int *out, int *comp, int *ord,
           int *cadr) {
  size_t sz = sizeof(int) * (size_t)(nn + 1);
  scc_work W = {bg_xmalloc(sz), bg_xmalloc(sz), bg_xmalloc(sz), bg_xmalloc(sz), bg_xmalloc(sz),
                bg_xcalloc((size_t)nn + 1, 1), 0, 0, 0};
  int nc = 0, no = 0;
  for (int v = 0; v < nn; v++) W.index[v] = -1;
  for (int r = 0; r < nn; r++) {
    if (W.index[r] >= 0) continue;
    scc_visit(&W, r);
    while (W.fp > 0) {
      int v = W.fv[W.fp - 1];
      if (W.fpos[W.fp - 1] < deg[v]) {
        int w = out[adr[v] + W.fpos[W.fp - 1]++];
        if (W.index[w] < 0) scc_visit(&W, w);
        else if (W.on[w] && W.index[w] < W.low[v]) W.low[v] = W.index[w];
        continue;
      }
      if (W.low[v] == W.index[v]) { /* v roots a component: release it */
        if (cadr) cadr[nc] = no;
        int w;
        do {
          w = W.stk[--W.sp];
          W.on[w] = 0;
          comp[w] = nc;
          if (ord) ord[no++] = w;
        } while (w != v);
        nc++;
      }
      if (--W.fp > 0 && W.low[v] < W.low[W.fv[W.fp - 1]]) W.low[W.fv[W.fp - 1]] = W.low[v];
    }
  }
  if (cadr) cadr[nc] = no;
  free(W.index), free(W.low), free(W.stk), free(W.fv), free(W.fpos), free(W.on);
  return nc;
}
