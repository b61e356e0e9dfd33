/* prism.c: the machinery polygon, prism and text share (prism.h): an outline
 * of edges swept between two heights, on the host in double precision and
 * lowered into PRIM_PRISM records for kernels/shape_prism.cl. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lower.h"
#include "prism.h"

static int glyph_start(const scene_outline *ol, int g)
{
	return ol->glyph ? ol->glyph[g] : g == 0 ? 0 : ol->n_edges;
}

prism_view prism_view_of(const scene *s, const scene_object *o)
{
	prism_view v = { .ol = &s->outlines[o->outline], .local = scene_xform_identity() };
	v.last = v.ol->glyph ? v.ol->n_glyphs : 1;
	switch (o->shape) {
	case SHAPE_POLYGON:
		v.flags = PRISM_FLAT;
		for (int i = 0; i < 3; i++) {
			for (int j = 0; j < 3; j++)
				v.local.m[i][j] = o->n[j][i];
			v.local.m[i][3] = o->p[0][i];
		}
		break;
	case SHAPE_TEXT:
		v.h2 = o->radius;
		memset(v.local.m, 0, sizeof v.local.m);
		v.local.m[0][0] = v.local.m[1][2] = v.local.m[2][1] = 1;
		break;
	default:
		v.h1 = o->radius;
		v.h2 = o->param[0];
		v.flags = (o->shape_flags & SHAPE_OPEN ? PRISM_OPEN : 0) | (o->param[1] != 0 ? PRISM_CONIC : 0);
	}
	if (lower_invert(&v.local, &v.inverse))
		v.inverse = scene_xform_identity();   /* the frames above are never singular */
	return v;
}

/* ---- the plane ---- */

/* Whether the half-line from (x, z) along +x crosses the edge: its z range
 * half open, so that a vertex two edges share counts once. */
static bool crosses(const double *e, double x, double z)
{
	if ((e[1] > z) == (e[3] > z))
		return false;
	return x < e[0] + (z - e[1]) * (e[2] - e[0]) / (e[3] - e[1]);
}

bool prism_in_outline(const scene_outline *ol, int first, int last, double x, double z)
{
	for (int g = first; g < last; g++) {
		bool odd = false;
		for (int i = glyph_start(ol, g); i < glyph_start(ol, g + 1); i++)
			odd ^= crosses(ol->edge[i], x, z);
		if (odd)
			return true;
	}
	return false;
}

/* The box of edges [a, b) in the plane: xmin, zmin, xmax, zmax. */
static void plane_box(const scene_outline *ol, int a, int b, double box[4])
{
	box[0] = box[1] = INFINITY;
	box[2] = box[3] = -INFINITY;
	for (int i = a; i < b; i++)
		for (int k = 0; k < 4; k += 2) {
			box[0] = fmin(box[0], ol->edge[i][k]);
			box[1] = fmin(box[1], ol->edge[i][k + 1]);
			box[2] = fmax(box[2], ol->edge[i][k]);
			box[3] = fmax(box[3], ol->edge[i][k + 1]);
		}
}

/* Whether the half-line from m along n crosses edge e (e's own start counts,
 * its end does not). */
static bool ray_crosses(const double m[2], const double n[2], const double *e)
{
	double ex = e[2] - e[0], ez = e[3] - e[1];
	double den = n[0] * ez - n[1] * ex;
	if (den == 0)
		return false;
	double wx = e[0] - m[0], wz = e[1] - m[1];
	double u = (wx * ez - wz * ex) / den, s = (wx * n[1] - wz * n[0]) / den;
	return u > 0 && s >= 0 && s < 1;
}

void prism_orient(scene_outline *ol)
{
	int glyphs = ol->glyph ? ol->n_glyphs : 1, kept = 0;
	for (int g = 0; g < glyphs; g++) {
		int a = glyph_start(ol, g), b = glyph_start(ol, g + 1);
		for (int i = a; i < b; i++) {
			double *e = ol->edge[i];
			double m[2] = { (e[0] + e[2]) / 2, (e[1] + e[3]) / 2 }, n[2] = { e[3] - e[1], e[0] - e[2] };
			if (n[0] == 0 && n[1] == 0)
				continue;
			bool odd = false;
			for (int j = a; j < b; j++)
				if (j != i)
					odd ^= ray_crosses(m, n, ol->edge[j]);
			if (odd) {   /* the inside is on the side of n: turn the edge */
				double x = e[0], z = e[1];
				e[0] = e[2];
				e[1] = e[3];
				e[2] = x;
				e[3] = z;
			}
		}
		/* edges of no length go: they bound nothing */
		if (ol->glyph)
			ol->glyph[g] = kept;
		for (int i = a; i < b; i++)
			if (ol->edge[i][0] != ol->edge[i][2] || ol->edge[i][1] != ol->edge[i][3])
				memmove(ol->edge[kept++], ol->edge[i], sizeof ol->edge[i]);
	}
	if (ol->glyph)
		ol->glyph[glyphs] = kept;
	ol->n_edges = kept;
}

/* ---- the solid ---- */

/* The box of glyphs [first, last) in prism space. */
static bool local_box(const prism_view *v, int first, int last, double lo[3], double hi[3])
{
	int a = glyph_start(v->ol, first), b = glyph_start(v->ol, last);
	if (a >= b)
		return false;
	double box[4];
	plane_box(v->ol, a, b, box);
	double sx[2] = { box[0], box[2] }, sz[2] = { box[1], box[3] };
	if (v->flags & PRISM_CONIC) {   /* the outline scaled by h1 and by h2 */
		double xs[4] = { box[0] * v->h1, box[0] * v->h2, box[2] * v->h1, box[2] * v->h2 };
		double zs[4] = { box[1] * v->h1, box[1] * v->h2, box[3] * v->h1, box[3] * v->h2 };
		sx[0] = fmin(fmin(xs[0], xs[1]), fmin(xs[2], xs[3]));
		sx[1] = fmax(fmax(xs[0], xs[1]), fmax(xs[2], xs[3]));
		sz[0] = fmin(fmin(zs[0], zs[1]), fmin(zs[2], zs[3]));
		sz[1] = fmax(fmax(zs[0], zs[1]), fmax(zs[2], zs[3]));
	}
	double l[3] = { sx[0], v->h1, sz[0] }, h[3] = { sx[1], v->h2, sz[1] };
	memcpy(lo, l, sizeof l);
	memcpy(hi, h, sizeof h);
	return true;
}

void prism_bounds(const prism_view *v, const xform *xf, double lo[3], double hi[3])
{
	double a[3], b[3];
	if (!local_box(v, v->first, v->last, a, b))
		return;
	xform to_world = scene_xform_then(&v->local, xf);
	shape_grow_xformed_box(&to_world, a, b, lo, hi);
}

/* Whether a point of prism space is in the solid (POV-Ray's Inside: h1 <= y < h2). */
static bool inside_local(const prism_view *v, const double q[3])
{
	if (v->flags & PRISM_FLAT || !(q[1] >= v->h1 && q[1] < v->h2))
		return false;
	double x = q[0], z = q[2];
	if (v->flags & PRISM_CONIC) {
		if (fabs(q[1]) < 1e-10)
			return false;
		x /= q[1];
		z /= q[1];
	}
	return prism_in_outline(v->ol, v->first, v->last, x, z);
}

bool prism_inside(const prism_view *v, const double p[3])
{
	double q[3];
	scene_xform_point(&v->inverse, p, q);
	return inside_local(v, q);
}

/* A side's hit: edge e swept straight (or toward the apex, conic) between the
 * heights. */
static void side_hit(const prism_view *v, const double *e, const double o[3], const double d[3], double tmin,
                     double *best, double n[3])
{
	double ex = e[2] - e[0], ez = e[3] - e[1], t, s;
	double out[3] = { ez, 0, -ex };
	if (v->flags & PRISM_CONIC) {
		/* the plane through the apex and the edge at height 1 */
		out[1] = -(ez * e[0] - ex * e[1]);
		double den = out[0] * d[0] + out[1] * d[1] + out[2] * d[2];
		if (den == 0)
			return;
		t = -(out[0] * o[0] + out[1] * o[1] + out[2] * o[2]) / den;
		double y = o[1] + t * d[1];
		if (y == 0)
			return;
		double px = (o[0] + t * d[0]) / y - e[0], pz = (o[2] + t * d[2]) / y - e[1];
		s = (px * ex + pz * ez) / (ex * ex + ez * ez);
		if (y < 0)
			for (int k = 0; k < 3; k++)
				out[k] = -out[k];
	} else {
		double den = d[0] * ez - d[2] * ex;
		if (den == 0)
			return;
		double wx = e[0] - o[0], wz = e[1] - o[2];
		t = (wx * ez - wz * ex) / den;
		s = (wx * d[2] - wz * d[0]) / den;
	}
	double y = o[1] + t * d[1];
	if (!(t > tmin && t < *best && s >= 0 && s <= 1 && y >= v->h1 && y <= v->h2))
		return;
	*best = t;
	memcpy(n, out, sizeof out);
}

void prism_trace(const prism_view *v, const double ro[3], const double rd[3], double tmin, shape_hit *h)
{
	double o[3], d[3], n[3] = { 0, 0, 0 }, best = h->t;
	scene_xform_point(&v->inverse, ro, o);
	scene_xform_vector(&v->inverse, rd, d);
	int caps = v->flags & PRISM_FLAT ? 1 : v->flags & PRISM_OPEN ? 0 : 2;
	for (int c = 0; c < caps && d[1] != 0; c++) {
		double hc = c ? v->h2 : v->h1, t = (hc - o[1]) / d[1];
		if (!(t > tmin && t < best))
			continue;
		double x = o[0] + t * d[0], z = o[2] + t * d[2];
		if (v->flags & PRISM_CONIC) {
			if (hc == 0)
				continue;
			x /= hc;
			z /= hc;
		}
		if (prism_in_outline(v->ol, v->first, v->last, x, z)) {
			best = t;
			n[0] = n[2] = 0;
			n[1] = c ? 1 : -1;
		}
	}
	if (!(v->flags & PRISM_FLAT))
		for (int i = glyph_start(v->ol, v->first); i < glyph_start(v->ol, v->last); i++)
			side_hit(v, v->ol->edge[i], o, d, tmin, &best, n);
	if (best >= h->t)
		return;
	h->t = best;
	for (int j = 0; j < 3; j++)   /* normals map by the transpose of the inverse */
		h->n[j] = v->inverse.m[0][j] * n[0] + v->inverse.m[1][j] * n[1] + v->inverse.m[2][j] * n[2];
}

/* ---- lowering ---- */

static float4 f4(double x, double y, double z, double w)
{
	return (float4){ (float)x, (float)y, (float)z, (float)w };
}

static float4 ints(int x, int y, int z, int w)
{
	int v[4] = { x, y, z, w };
	float4 f;
	memcpy(&f, v, sizeof f);
	return f;
}

/* One primitive for glyphs [first, last). */
static void lower_glyphs(struct lowering *lw, const prism_view *v, const xform *to_world, int first, int last,
                         int mat, int id)
{
	const scene_outline *ol = v->ol;
	int a = glyph_start(ol, first), b = glyph_start(ol, last);
	if (a >= b)
		return;
	dev_prim p = { .type = PRIM_PRISM };
	if (lower_local_rows(to_world, &p))
		return;   /* the caller said so already */
	int chunks = 0;
	for (int g = first; g < last; g++)
		chunks += (glyph_start(ol, g + 1) - glyph_start(ol, g) + PRISM_CHUNK - 1) / PRISM_CHUNK;
	double box[4];
	plane_box(ol, a, b, box);
	float4 head = ints(0, 0, chunks, v->flags);
	head.x = (float)v->h1;
	head.y = (float)v->h2;
	p.link = lower_add_data(lw, head);
	lower_add_data(lw, f4(box[0], box[1], box[2], box[3]));
	for (int g = first; g < last; g++) {
		int ga = glyph_start(ol, g), gb = glyph_start(ol, g + 1);
		for (int c = ga; c < gb; c += PRISM_CHUNK) {
			int n = gb - c < PRISM_CHUNK ? gb - c : PRISM_CHUNK;
			double cb[4];
			plane_box(ol, c, c + n, cb);
			lower_add_data(lw, f4(cb[0], cb[1], cb[2], cb[3]));
			lower_add_data(lw, ints(n, c == ga, 0, 0));
			for (int i = c; i < c + n; i++)
				lower_add_data(lw, f4(ol->edge[i][0], ol->edge[i][1], ol->edge[i][2], ol->edge[i][3]));
		}
	}
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY }, l[3], h[3];
	local_box(v, first, last, l, h);
	shape_grow_xformed_box(to_world, l, h, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
}

int prism_lower(struct lowering *lw, const prism_view *v, const scene_object *o, int mat, int id)
{
	xform to_world = scene_xform_then(&v->local, &o->xf);
	dev_prim p;
	if (lower_local_rows(&to_world, &p)) {
		diag_warning(o->loc, "%s with a singular transform (a scale of 0?) skipped", shape_of(o)->name);
		return 0;
	}
	if (lower_in_csg(lw)) {
		lower_glyphs(lw, v, &to_world, v->first, v->last, mat, id);
		return 0;
	}
	for (int g = v->first; g < v->last; g++)
		lower_glyphs(lw, v, &to_world, g, g + 1, mat, id);
	return 0;
}

/* ---- the class functions of polygon, prism and text (shape_polygon.c,
 * shape_prism.c, shape_text.c) ---- */

void prism_shape_bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	prism_view v = prism_view_of(s, o);
	prism_bounds(&v, &o->xf, lo, hi);
}

void prism_shape_trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                       shape_hit *h)
{
	prism_view v = prism_view_of(s, o);
	prism_trace(&v, ro, rd, tmin, h);
}

bool prism_shape_inside(const scene *s, const scene_object *o, const double p[3])
{
	prism_view v = prism_view_of(s, o);
	return prism_inside(&v, p);
}

int prism_shape_lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	prism_view v = prism_view_of(s, o);
	return prism_lower(lw, &v, o, mat, id);
}
