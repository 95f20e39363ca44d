/* SPDX-License-Identifier: BSD-3-Clause */
/* The phase of a frequency response, continuous along the frequencies.
 * Unwrapping the sampled angles (taking every step above 180 degrees as a
 * wrap) fails where the true phase moves by more than 180 degrees between
 * two samples: a lightly damped pole pair nearly cancelled by a zero pair
 * swings the phase through almost 180 degrees and back inside a band far
 * narrower than the sample spacing, and the unwrapped curve then stays
 * 360 degrees off for every later frequency. The factored form
 * K prod(jw - z) / prod(jw - p) has a phase that is a sum of one angle per
 * root, each continuous in w for a root off the imaginary axis, so it tells
 * the branch of each sample exactly; the sample's own angle keeps the value. */
#include <math.h>

#include "linear/linear.h"

#define DEG (180 / 3.14159265358979323846)

/* The angle of jw - r in degrees, continuous in w >= 0: in (-90, 90) for a
 * root in the left half plane, (90, 270) in the right one, +-90 on the axis. */
static double root_angle(double w, double re, double im) {
  double a = atan2(w - im, -re) * DEG;
  return re > 0 && a < 0 ? a + 360 : a;
}

static double factored(const bg_lin_tf *t, double w) {
  double a = 0;
  for (int i = 0; i < t->nzero; i++) a += root_angle(w, t->zero_re[i], t->zero_im[i]);
  for (int i = 0; i < t->npole; i++) a -= root_angle(w, t->pole_re[i], t->pole_im[i]);
  return a;
}

/* Each sample's own angle in (-180, 180]; NaN where H is 0. */
static void sample_angles(int nw, const double *re, const double *im, double *ph) {
  for (int k = 0; k < nw; k++) ph[k] = re[k] == 0 && im[k] == 0 ? NAN : atan2(im[k], re[k]) * DEG;
}

/* Samples' steps above 180 degrees taken as wraps (no factored form). */
static void unwrap(double *ph, int n) {
  for (int k = 1; k < n; k++) {
    if (!isfinite(ph[k]) || !isfinite(ph[k - 1])) continue;
    while (ph[k] - ph[k - 1] > 180) ph[k] -= 360;
    while (ph[k] - ph[k - 1] < -180) ph[k] += 360;
  }
}

/* Where the factored form and a sample disagree by more than this (inexact
 * roots of a large or ill-conditioned model), the samples are unwrapped. */
#define PHASE_AGREE 30.0

void bg_linear_phase(const bg_linear *l, int pair, int nw, const double *w, const double *re,
                     const double *im, double *ph) {
  sample_angles(nw, re, im, ph);
  const bg_lin_tf *t = pair < l->ntf && l->tf ? &l->tf[pair] : NULL;
  if (!t) {
    unwrap(ph, nw);
    return;
  }
  /* the constant (arg K, 0 or 180 modulo 360) from the first finite sample,
   * which keeps its angle in (-180, 180] as the unwrapped curve did */
  int k0 = 0;
  while (k0 < nw && !isfinite(ph[k0])) k0++;
  if (k0 == nw) return;
  double c = ph[k0] - factored(t, w[k0]);
  for (int k = k0; k < nw; k++) {
    if (!isfinite(ph[k])) continue;
    double f = factored(t, w[k]) + c, d = remainder(ph[k] - f, 360);
    if (fabs(d) > PHASE_AGREE) {
      sample_angles(nw, re, im, ph); /* the samples before k were moved already */
      unwrap(ph, nw);
      return;
    }
    ph[k] = f + d;
  }
}
