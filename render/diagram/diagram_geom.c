/* Page geometry of the diagram: vectors, where bonds run, barbs, arrowheads. */
#include <math.h>

#include "diagram/diagram_int.h"

bg_vec bg_v(double x, double y) { return (bg_vec){x, y}; }
bg_vec bg_vadd(bg_vec a, bg_vec b) { return bg_v(a.x + b.x, a.y + b.y); }
bg_vec bg_vsub(bg_vec a, bg_vec b) { return bg_v(a.x - b.x, a.y - b.y); }
bg_vec bg_vscale(bg_vec a, double k) { return bg_v(a.x * k, a.y * k); }
double bg_vlen(bg_vec a) { return hypot(a.x, a.y); }
bg_vec bg_vleft(bg_vec d) { return bg_v(d.y, -d.x); }

bg_vec bg_vunit(bg_vec a) {
  double n = bg_vlen(a);
  return n > 1e-12 ? bg_vscale(a, 1 / n) : bg_v(1, 0);
}

bg_vec bg_box_exit(bg_vec c, double hw, double hh, bg_vec p) {
  bg_vec dv = bg_vsub(p, c);
  double tx = fabs(dv.x) > 1e-12 ? hw / fabs(dv.x) : 1e300;
  double ty = fabs(dv.y) > 1e-12 ? hh / fabs(dv.y) : 1e300;
  double t = tx < ty ? tx : ty;
  if (t > 1) t = 1; /* overlapping boxes: stop at the other centre */
  return bg_vadd(c, bg_vscale(dv, t));
}

static bg_vec node_centre(const bg_diagram *d, int n) { return bg_v(d->nx[n], d->ny[n]); }

static void straight_geom(const bg_diagram *d, int t, int h, bg_bond_geom *g) {
  bg_vec ct = node_centre(d, t), ch = node_centre(d, h);
  g->tail = bg_box_exit(ct, d->nw[t] / 2, d->nh[t] / 2, ch);
  g->head = bg_box_exit(ch, d->nw[h] / 2, d->nh[h] / 2, ct);
  g->tdir = g->hdir = g->mdir = bg_vunit(bg_vsub(ch, ct));
  g->mid = bg_vscale(bg_vadd(g->tail, g->head), 0.5);
}

static bg_vec spl_pt(const bg_diagram *d, int i) { return bg_v(d->splx[i], d->sply[i]); }

/* Point and derivative of one cubic piece at t. */
static void bezier_eval(const bg_vec p[4], double t, bg_vec *pt, bg_vec *dt) {
  double u = 1 - t;
  pt->x = u * u * u * p[0].x + 3 * u * u * t * p[1].x + 3 * u * t * t * p[2].x + t * t * t * p[3].x;
  pt->y = u * u * u * p[0].y + 3 * u * u * t * p[1].y + 3 * u * t * t * p[2].y + t * t * t * p[3].y;
  dt->x = 3 * u * u * (p[1].x - p[0].x) + 6 * u * t * (p[2].x - p[1].x) + 3 * t * t * (p[3].x - p[2].x);
  dt->y = 3 * u * u * (p[1].y - p[0].y) + 6 * u * t * (p[2].y - p[1].y) + 3 * t * t * (p[3].y - p[2].y);
}

static void spline_geom(const bg_diagram *d, int adr, int n, bg_bond_geom *g) {
  g->spladr = adr, g->spln = n;
  g->tail = spl_pt(d, adr);
  g->head = spl_pt(d, adr + n - 1);
  g->tdir = bg_vunit(bg_vsub(spl_pt(d, adr + 1), g->tail));
  g->hdir = bg_vunit(bg_vsub(g->head, spl_pt(d, adr + n - 2)));
  int pieces = (n - 1) / 3, piece = pieces / 2;
  bg_vec p[4], dt;
  for (int k = 0; k < 4; k++) p[k] = spl_pt(d, adr + 3 * piece + k);
  bezier_eval(p, pieces % 2 ? 0.5 : 0.0, &g->mid, &dt);
  g->mdir = bg_vlen(dt) > 1e-9 ? bg_vunit(dt) : bg_vunit(bg_vsub(g->head, g->tail));
}

void bg_geom_bonds(bg_diagram *d) {
  const bg_model *m = d->m;
  for (int b = 0; b < m->nbond; b++) {
    bg_bond_geom *g = &d->bg[b];
    int n = d->lay.spln ? d->lay.spln[b] : 0;
    if (n >= 4 && (n - 1) % 3 == 0) spline_geom(d, d->lay.spladr[b], n, g);
    else straight_geom(d, m->bond_tail[b], m->bond_head[b], g);
  }
}

bg_vec bg_barb_side(const bg_diagram *d, int b) {
  bg_vec dir = d->bg[b].hdir, left = bg_vleft(dir);
  if (d->st.harpoon == BG_HARPOON_LEFT) return left;
  /* "down": below horizontal bonds, right of vertical ones (y grows downwards) */
  if (fabs(dir.x) >= fabs(dir.y)) return left.y > 0 ? left : bg_vscale(left, -1);
  return left.x > 0 ? left : bg_vscale(left, -1);
}

void bg_geom_bond_path(const bg_diagram *d, int b) {
  const bg_bond_geom *g = &d->bg[b];
  bg_scene *s = (bg_scene *)&d->scene;
  bg_scene_move(s, g->tail.x, g->tail.y);
  if (!g->spln) {
    bg_scene_line(s, g->head.x, g->head.y);
    return;
  }
  for (int i = 1; i + 2 < g->spln; i += 3) {
    bg_vec p1 = spl_pt(d, g->spladr + i), p2 = spl_pt(d, g->spladr + i + 1),
           p3 = spl_pt(d, g->spladr + i + 2);
    bg_scene_curve(s, p1.x, p1.y, p2.x, p2.y, p3.x, p3.y);
  }
}

void bg_geom_arrowhead(bg_scene *s, bg_vec p, bg_vec dir, double len, double wid) {
  bg_vec u = bg_vunit(dir), n = bg_vleft(u);
  bg_vec back = bg_vsub(p, bg_vscale(u, len));
  bg_vec a = bg_vadd(back, bg_vscale(n, wid / 2)), c = bg_vsub(back, bg_vscale(n, wid / 2));
  bg_scene_move(s, p.x, p.y);
  bg_scene_line(s, a.x, a.y);
  bg_scene_line(s, c.x, c.y);
  bg_scene_close(s);
}
