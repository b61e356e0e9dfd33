/* shape_sphere_sweep.c: sphere_sweep { linear_spline | b_spline | cubic_spline
 * Number, <Centre>, Radius... [tolerance T] }, POV-Ray 3.7's sphere sweep
 * (sphsweep.cpp): the space a sphere fills as its centre and radius move along
 * a spline. Each segment of the spline is a centre C(u) and a radius r(u)
 * polynomial in u over [0, 1]: linear between two modelling spheres (a cone
 * tangent to both, with the spheres at its ends), or cubic over four of them
 * with POV-Ray's Catmull-Rom (cubic_spline) or uniform B-spline (b_spline)
 * matrix, the segments overlapping by three spheres. The sweep is the union of
 * the segments, and a segment the union of its spheres for u in [0, 1].
 * src/eval_sweep.c reads it: its spheres are scene.outlines[o->outline]'s
 * edges, (x, y, z, radius) each; param[0] the spline (SWEEP_), param[1] the
 * tolerance.
 *
 * A ray meets a segment's surface on the sphere at u where it also meets the
 * envelope, d/du |X - C(u)|^2 - r(u)^2 = 0: eliminating the ray's t leaves a
 * polynomial in u of degree 10 (2 for a linear segment), as in POV-Ray, whose
 * roots in [0, 1] (src/roots.c) give the spheres to intersect; the spheres at
 * the segments' ends close them. Of those points, the ones on the sweep's
 * surface are those not inside another part of it (POV-Ray counts its way in
 * and out of the parts along the whole line instead; the surface is the same).
 * The normal and the inside test come from the power distance
 * |X - C(u)|^2 - r(u)^2 minimised over every segment and u: the sweep is where
 * it is negative, and its gradient 2 (X - C(u*)) is the outward normal.
 * kernels/shape_sphere_sweep.cl does the same, which the device is held to
 * (tests/test_sweep.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ast.h"
#include "lower.h"
#include "roots.h"
#include "shape.h"
#include "sweep.h"
#include "vec3.h"

/* POV-Ray's basis matrices: row k gives the weights of the four spheres in u^k. */
static const double catmull_rom[4][4] = {
	{ 0, 1, 0, 0 }, { -0.5, 0, 0.5, 0 }, { 1, -2.5, 2, -0.5 }, { -0.5, 1.5, -1.5, 0.5 },
};
static const double b_spline[4][4] = {
	{ 1 / 6.0, 4 / 6.0, 1 / 6.0, 0 }, { -0.5, 0, 0.5, 0 }, { 0.5, -1, 0.5, 0 }, { -1 / 6.0, 0.5, -0.5, 1 / 6.0 },
};

int sweep_segments(const scene *s, const scene_object *o)
{
	int n = s->outlines[o->outline].n_edges;
	return (int)o->param[0] == SWEEP_LINEAR ? n - 1 : n - 3;
}

void sweep_segment(const scene *s, const scene_object *o, int i, sweep_seg *g)
{
	const double (*sp)[4] = (const double (*)[4])s->outlines[o->outline].edge + i;
	memset(g, 0, sizeof *g);
	int kind = (int)o->param[0];
	if (kind == SWEEP_LINEAR) {
		for (int k = 0; k < 4; k++) {
			g->c[0][k] = sp[0][k];
			g->c[1][k] = sp[1][k] - sp[0][k];
		}
		g->order = 1;
	} else {
		const double (*m)[4] = kind == SWEEP_CUBIC ? catmull_rom : b_spline;
		for (int k = 0; k < 4; k++)
			for (int j = 0; j < 4; j++)
				for (int q = 0; q < 4; q++)
					g->c[k][q] += m[k][j] * sp[j][q];
		g->order = 3;
	}
	/* a box around the segment: its Bezier control points hold the curve and
	 * bound the radius */
	double b[4][4];
	for (int q = 0; q < 4; q++) {
		b[0][q] = g->c[0][q];
		b[1][q] = g->c[0][q] + g->c[1][q] / 3;
		b[2][q] = g->c[0][q] + 2 * g->c[1][q] / 3 + g->c[2][q] / 3;
		b[3][q] = g->c[0][q] + g->c[1][q] + g->c[2][q] + g->c[3][q];
	}
	double rmax = 0;
	for (int j = 0; j < 4; j++)
		rmax = fmax(rmax, fabs(b[j][3]));
	for (int q = 0; q < 3; q++) {
		g->lo[q] = fmin(fmin(b[0][q], b[1][q]), fmin(b[2][q], b[3][q])) - rmax;
		g->hi[q] = fmax(fmax(b[0][q], b[1][q]), fmax(b[2][q], b[3][q])) + rmax;
	}
}

/* The centre and radius at u into cr. */
static void at(const sweep_seg *g, double u, double cr[4])
{
	for (int q = 0; q < 4; q++)
		cr[q] = ((g->c[3][q] * u + g->c[2][q]) * u + g->c[1][q]) * u + g->c[0][q];
}

/* The least power distance |x - C(u)|^2 - r(u)^2 over u in [0, 1], and its u
 * into *best_u. */
static double least_power(const sweep_seg *g, const double x[3], double *best_u)
{
	/* f(u) = |W(u)|^2 - r(u)^2 with W = x - C: degree 6 */
	double w[4][3], f[7] = { 0 };
	for (int k = 0; k < 4; k++)
		for (int q = 0; q < 3; q++)
			w[k][q] = (k == 0 ? x[q] : 0) - g->c[k][q];
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++)
			f[i + j] += vec3_dot(w[i], w[j]) - g->c[i][3] * g->c[j][3];
	double df[6], u[6], cr[4];
	for (int k = 0; k < 6; k++)
		df[k] = (k + 1) * f[k + 1];
	int n = roots_find(df, 5, 0, 1, u, 6);
	double best = INFINITY;
	for (int i = -1; i <= n; i++) {
		double v = i < 0 ? 0 : i == n ? 1 : u[i];
		at(g, v, cr);
		double d[3] = { x[0] - cr[0], x[1] - cr[1], x[2] - cr[2] }, p = vec3_dot(d, d) - cr[3] * cr[3];
		if (p < best)
			best = p, *best_u = v;
	}
	return best;
}

/* The least power distance from x over the segments (over those whose box
 * holds x when near is set: the others' is positive), with its segment and u
 * into *seg and *u; INFINITY when none is looked at. A point of the surface
 * is in its segment's box, so the normal looks near too, and everywhere only
 * when rounding has put it outside every box. */
static double least_over(const sweep_seg *segs, int n, const double x[3], bool near, double slack, int *seg,
                         double *u)
{
	double best = INFINITY;
	for (int j = 0; j < n; j++) {
		const sweep_seg *g = &segs[j];
		if (near && (x[0] < g->lo[0] - slack || x[0] > g->hi[0] + slack || x[1] < g->lo[1] - slack ||
		             x[1] > g->hi[1] + slack || x[2] < g->lo[2] - slack || x[2] > g->hi[2] + slack))
			continue;
		double v, p = least_power(g, x, &v);
		if (p < best)
			best = p, *seg = j, *u = v;
	}
	return best;
}

/* Whether x is deeper than eps inside a segment: then it is no point of the
 * sweep's surface. */
static bool deep_inside(const sweep_seg *segs, int n, const double x[3], double eps)
{
	for (int j = 0; j < n; j++) {
		const sweep_seg *g = &segs[j];
		if (x[0] < g->lo[0] || x[0] > g->hi[0] || x[1] < g->lo[1] || x[1] > g->hi[1] || x[2] < g->lo[2] ||
		    x[2] > g->hi[2])
			continue;
		double v, cr[4], p = least_power(g, x, &v);
		if (!(p < 0))
			continue;
		at(g, v, cr);
		double r = fabs(cr[3]);   /* the depth r - |x - C| */
		if (r - sqrt(fmax(r * r + p, 0)) > eps)
			return true;
	}
	return false;
}

/* The ray's hits with the sphere cr in (lo, hi) into t[], two at most. */
static int sphere_hits(const double cr[4], const double o[3], const double d[3], double lo, double hi, double t[2])
{
	double w[3] = { o[0] - cr[0], o[1] - cr[1], o[2] - cr[2] };
	double A = vec3_dot(d, d), B = vec3_dot(w, d), C = vec3_dot(w, w) - cr[3] * cr[3], disc = B * B - A * C;
	if (!(disc > 0) || !(A > 0))
		return 0;
	double q = sqrt(disc), r[2] = { (-B - q) / A, (-B + q) / A };
	int n = 0;
	for (int k = 0; k < 2; k++)
		if (r[k] > lo && r[k] < hi)
			t[n++] = r[k];
	return n;
}

/* The u in [0, 1] where the ray touches the envelope of segment g: the roots
 * of A P^2 - 2 P Q B + Q^2 E, where t = -P/Q solves d/du of the power
 * distance along the ray and B, E are the ray's power distance's terms. */
static int envelope_roots(const sweep_seg *g, const double o[3], const double d[3], double *u)
{
	double w[4][3], dc[3][3], dr[3], P[6] = { 0 }, Q[3], B[4], E[7] = { 0 }, F[11] = { 0 };
	for (int k = 0; k < 4; k++)
		for (int q = 0; q < 3; q++)
			w[k][q] = (k == 0 ? o[q] : 0) - g->c[k][q];
	for (int k = 0; k < 3; k++) {
		for (int q = 0; q < 3; q++)
			dc[k][q] = (k + 1) * g->c[k + 1][q];
		dr[k] = (k + 1) * g->c[k + 1][3];
		Q[k] = vec3_dot(d, dc[k]);
	}
	for (int i = 0; i < 4; i++) {
		B[i] = vec3_dot(d, w[i]);
		for (int j = 0; j < 4; j++)
			E[i + j] += vec3_dot(w[i], w[j]) - g->c[i][3] * g->c[j][3];
		for (int j = 0; j < 3; j++)
			P[i + j] += vec3_dot(w[i], dc[j]) + g->c[i][3] * dr[j];
	}
	double A = vec3_dot(d, d);
	for (int i = 0; i < 6; i++)
		for (int j = 0; j < 6; j++) {
			F[i + j] += A * P[i] * P[j];
			if (j < 3) {
				for (int k = 0; k < 4; k++)
					F[i + j + k] -= 2 * P[i] * Q[j] * B[k];
			}
		}
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			for (int k = 0; k < 7; k++)
				F[i + j + k] += Q[i] * Q[j] * E[k];
	return roots_find(F, 10, -1e-12, 1, u, 10);
}

/* The widest side of the segments' box: what eps scales with. */
static double size_of(const sweep_seg *segs, int n)
{
	double m = 0;
	for (int q = 0; q < 3; q++) {
		double lo = INFINITY, hi = -INFINITY;
		for (int j = 0; j < n; j++)
			lo = fmin(lo, segs[j].lo[q]), hi = fmax(hi, segs[j].hi[q]);
		m = fmax(m, hi - lo);
	}
	return m;
}

/* A candidate t: the nearest so far when it is on the sweep's surface. */
static void candidate(const sweep_seg *segs, int n, const double o[3], const double d[3], double t, double eps,
                      double *best)
{
	if (!(t < *best))
		return;
	double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
	if (!deep_inside(segs, n, x, eps))
		*best = t;
}

double sweep_hit(const sweep_seg *segs, int n, const double o[3], const double d[3], double tmin, double tmax)
{
	double best = tmax, eps = 1e-7 * size_of(segs, n);
	for (int j = 0; j < n; j++) {
		const sweep_seg *g = &segs[j];
		/* the ray against the segment's box */
		double t0 = tmin, t1 = best;
		for (int q = 0; q < 3 && t0 <= t1; q++) {
			if (d[q] == 0) {
				if (o[q] < g->lo[q] || o[q] > g->hi[q])
					t0 = INFINITY;
				continue;
			}
			double a = (g->lo[q] - o[q]) / d[q], b = (g->hi[q] - o[q]) / d[q];
			t0 = fmax(t0, fmin(a, b));
			t1 = fmin(t1, fmax(a, b));
		}
		if (!(t0 <= t1))
			continue;
		double u[12], cr[4], t[2];
		int m = envelope_roots(g, o, d, u);
		u[m++] = 0;
		u[m++] = 1;
		for (int i = 0; i < m; i++) {
			at(g, u[i], cr);
			int k = sphere_hits(cr, o, d, tmin, best, t);
			for (int h = 0; h < k; h++)
				candidate(segs, n, o, d, t[h], eps, &best);
		}
	}
	return best;
}

/* ---- the class ---- */

static sweep_seg *segments(const scene *s, const scene_object *o, int *n)
{
	*n = sweep_segments(s, o);
	if (*n <= 0)
		return NULL;
	sweep_seg *g = malloc((size_t)*n * sizeof *g);
	if (!g)
		abort();
	for (int i = 0; i < *n; i++)
		sweep_segment(s, o, i, &g[i]);
	return g;
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	int n;
	sweep_seg *g = segments(s, o, &n);
	double len = sqrt(vec3_dot(rd, rd));
	if (!g || !(len > 0)) {
		free(g);
		return;
	}
	/* POV-Ray's tolerance: no hit nearer than it */
	double t = sweep_hit(g, n, ro, rd, fmax(tmin, o->param[1] / len), h->t);
	if (t < h->t) {
		double x[3] = { ro[0] + t * rd[0], ro[1] + t * rd[1], ro[2] + t * rd[2] }, u = 0, cr[4];
		int j = 0;
		if (least_over(g, n, x, true, 1e-4 * size_of(g, n), &j, &u) == INFINITY)
			least_over(g, n, x, false, 0, &j, &u);
		at(&g[j], u, cr);
		h->t = t;
		for (int q = 0; q < 3; q++)
			h->n[q] = x[q] - cr[q];
		if (h->n[0] == 0 && h->n[1] == 0 && h->n[2] == 0)
			h->n[1] = 1;
	}
	free(g);
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	int n, j;
	double u;
	sweep_seg *g = segments(s, o, &n);
	bool in = g && least_over(g, n, p, true, 0, &j, &u) < 0;
	free(g);
	return in;
}

/* POV-Ray's box (the modelling spheres, twice their radii for cubic_spline,
 * which its segments may leave), with the segments' own boxes, which hold
 * them wherever the spline goes. */
static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	const scene_outline *ol = &s->outlines[o->outline];
	double a[3] = { INFINITY, INFINITY, INFINITY }, b[3] = { -INFINITY, -INFINITY, -INFINITY };
	double k = (int)o->param[0] == SWEEP_CUBIC ? 2 : 1;
	for (int i = 0; i < ol->n_edges; i++)
		for (int q = 0; q < 3; q++) {
			a[q] = fmin(a[q], ol->edge[i][q] - k * ol->edge[i][3]);
			b[q] = fmax(b[q], ol->edge[i][q] + k * ol->edge[i][3]);
		}
	int n = sweep_segments(s, o);
	for (int i = 0; i < n; i++) {
		sweep_seg g;
		sweep_segment(s, o, i, &g);
		for (int q = 0; q < 3; q++) {
			a[q] = fmin(a[q], g.lo[q]);
			b[q] = fmax(b[q], g.hi[q]);
		}
	}
	if (a[0] <= b[0])
		shape_grow_xformed_box(&o->xf, a, b, lo, hi);
}

/* Segments a primitive of the top level holds: a ray meets the primitives
 * whose boxes it crosses (the BVH's), and tests only their segments' boxes,
 * so a long sweep costs a ray what its neighbourhood does. */
#define CHUNK 8

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	int n = sweep_segments(s, o);
	if (n <= 0)
		return 0;
	sweep_seg *g = segments(s, o, &n);
	/* the segments about the centre of their box, which the map to the
	 * sweep's space moves back: floats keep their digits far from the origin */
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY }, cen[3];
	for (int i = 0; i < n; i++)
		for (int q = 0; q < 3; q++)
			lo[q] = fmin(lo[q], g[i].lo[q]), hi[q] = fmax(hi[q], g[i].hi[q]);
	double size = 0;
	for (int q = 0; q < 3; q++) {
		cen[q] = 0.5 * (lo[q] + hi[q]);
		size = fmax(size, hi[q] - lo[q]);
	}
	xform move = scene_xform_translate(cen), to_world = scene_xform_then(&move, &o->xf);
	dev_prim p = { .type = PRIM_SPHERE_SWEEP };
	if (lower_local_rows(&to_world, &p)) {
		diag_warning(o->loc, "sphere_sweep with a singular transform (a scale of 0?) skipped");
		free(g);
		return 0;
	}
	int head = lower_add_data(lw, (float4){ (float)n, (float)o->param[1], (float)(1e-7 * size), 0 });
	for (int i = 0; i < n; i++) {
		g[i].c[0][0] -= cen[0], g[i].c[0][1] -= cen[1], g[i].c[0][2] -= cen[2];
		lower_add_data(lw, (float4){ (float)(g[i].lo[0] - cen[0]), (float)(g[i].lo[1] - cen[1]),
		                             (float)(g[i].lo[2] - cen[2]), 0 });
		lower_add_data(lw, (float4){ (float)(g[i].hi[0] - cen[0]), (float)(g[i].hi[1] - cen[1]),
		                             (float)(g[i].hi[2] - cen[2]), 0 });
		for (int k = 0; k < 4; k++)
			lower_add_data(lw, (float4){ (float)g[i].c[k][0], (float)g[i].c[k][1], (float)g[i].c[k][2],
			                             (float)g[i].c[k][3] });
	}
	/* a CSG's leaf is one primitive: then one chunk holds every segment */
	int chunk = lower_in_csg(lw) ? n : CHUNK;
	for (int first = 0, k = 0; first < n; first += chunk, k++) {
		int count = n - first < chunk ? n - first : chunk;
		/* its first segment, how many, and how far back the head is (the
		 * records are consecutive: the head, six a segment, the chunks) */
		p.link = lower_add_data(lw, (float4){ (float)first, (float)count, (float)(1 + 6 * n + k), 0 });
		double clo[3] = { INFINITY, INFINITY, INFINITY }, chi[3] = { -INFINITY, -INFINITY, -INFINITY };
		for (int i = first; i < first + count; i++)
			for (int q = 0; q < 3; q++)
				clo[q] = fmin(clo[q], g[i].lo[q]), chi[q] = fmax(chi[q], g[i].hi[q]);
		double blo[3] = { INFINITY, INFINITY, INFINITY }, bhi[3] = { -INFINITY, -INFINITY, -INFINITY };
		shape_grow_xformed_box(&o->xf, clo, chi, blo, bhi);
		lower_add_prim(lw, p, mat, id, blo, bhi);
	}
	free(g);
	return head < 0 ? -1 : 0;
}

static void dump(FILE *out, const scene_object *o)
{
	static const char *const kinds[] = { "linear_spline", "cubic_spline", "b_spline" };
	int k = (int)o->param[0];
	fprintf(out, "sphere_sweep %s outline %d tolerance ", kinds[k >= 0 && k < 3 ? k : 0], o->outline);
	scene_dump_num(out, o->param[1]);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_sphere_sweep = {
	.name = AST_WORD_SPHERE_SWEEP, .args = NULL, .needs = "a spline, a count and spheres",
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
