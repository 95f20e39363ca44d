/* SPDX-License-Identifier: BSD-3-Clause */
/* Printers: text and LaTeX of rlc and bond_loop, JSON shape. (The C export
 * is tested in test_export_c.c.) */
#include <stdio.h>
#include "harness.h"
#include "eqs_fixture.h"
#include "equations/equations.h"

static void test_text(void) {
  efx f;
  OK(efx_load(&f, "rlc", NULL, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_strbuf sb = {0};
  bg_eqprint_text(f.s, &sb);
  const char *t = bg_sb_str(&sb);
  OK(strstr(t, "# form: ODE x' = f(t, x); x = (L1.p, C1.q)") != NULL);
  OK(strstr(t, "e1 = V*step(t)\n") != NULL);
  OK(strstr(t, "f3 = L1.p/L0\n") != NULL);
  OK(strstr(t, "e2 = R0*f2\n") != NULL);
  OK(strstr(t, "e3 = e1 - e2 - e4\n") != NULL);
  OK(strstr(t, "L1.p' = e3\n") != NULL);
  OK(strstr(t, "C1.q' = f4\n") != NULL);
  bg_sb_clear(&sb);
  bg_eqprint_latex(f.s, &sb);
  OK(strstr(bg_sb_str(&sb), "\\dot{p_{\\mathrm{L1}}} &= e_{3}") != NULL);
  bg_sb_free(&sb);
  efx_free(&f);

  OK(efx_load(&f, "bond_loop", NULL, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_eqprint_text(f.s, &sb);
  t = bg_sb_str(&sb);
  OK(strstr(t, "z = (e4, f3)") != NULL);
  OK(strstr(t, "0 = e4 - n*e3    (solved for e4)") != NULL);
  OK(strstr(t, "0 = f3 - n*f4    (solved for f3)") != NULL);
  bg_sb_clear(&sb);
  OK(bg_eqprint(f.s, "json", &sb) == 0);
  OK(strstr(bg_sb_str(&sb), "{\"name\": \"e4\", \"kind\": \"algebraic\", \"initial\": 0, \"signal\": \"e4\"}") != NULL);
  OK(bg_eqprint(f.s, "xml", &sb) == -1);
  bg_sb_free(&sb);
  efx_free(&f);
}

/* A two-port whose modulus reads only states prints as its name, once, at
 * the top (found through the per-expression lookup, not a scan); a TF with
 * a constant modulus and an MTF modulated by a flow print the expression. */
static void test_modulus_names(void) {
  efx f;
  OK(efx_load(&f, "slider_crank", NULL, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_strbuf sb = {0};
  bg_eqprint_text(f.s, &sb);
  const char *t = bg_sb_str(&sb);
  OK(strstr(t, "\nT = rc*sin(phi)*") != NULL);
  OK(strstr(t, "f3 = T*f4\n") != NULL && strstr(t, "e4 = T*e3\n") != NULL);
  bg_sb_free(&sb);
  efx_free(&f);
  const char *src = "model tf2\nparam n = 2\nSe U = 1\n1 j\nTF A = n\nMTF B = 3 + n*j2.f\n"
                    "1 j2\nR R1 = 1\nR R2 = 1\nbond U -> j\nbond j -> A\nbond A -> j2\n"
                    "bond j2 -> R1\nbond j2 -> B\nbond B -> R2\n";
  OK(efx_load(&f, NULL, src, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_eqprint_text(f.s, &sb);
  t = bg_sb_str(&sb);
  OK(strstr(t, "\nA = ") == NULL && strstr(t, "\nB = ") == NULL);
  OK(strstr(t, "n*") != NULL);
  bg_sb_free(&sb);
  efx_free(&f);
}

int main(void) {
  test_text();
  test_modulus_names();
  return bg_t_done();
}
