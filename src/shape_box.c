/* shape_box.c: box { <Corner1>, <Corner2> }. On the device a box is the map
 * from world space to the cube [-1, 1]^3 about its centre, which its PRIM_DATA
 * record holds (kernels/shape_box.cl), so a rotated box is one primitive with
 * an inside, as precise far from the origin as near it. An emissive box outside CSG is twelve
 * triangles instead, so that the path tracer samples it as a light, and so is
 * a flat box (two corners sharing a coordinate), which has no inside. */
#include <math.h>
#include <string.h>

#include "lower.h"
#include "shape.h"

static void corners(const scene_object *o, double lo[3], double hi[3])
{
	for (int k = 0; k < 3; k++) {
		lo[k] = fmin(o->p[0][k], o->p[1][k]);
		hi[k] = fmax(o->p[0][k], o->p[1][k]);
	}
}

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	double a[3], b[3];
	corners(o, a, b);
	shape_grow_xformed_box(&o->xf, a, b, lo, hi);
}

/* The slabs: the entering face, or the leaving one from inside. */
static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	double lo[3], hi[3], t0 = -INFINITY, t1 = INFINITY;
	int axis0 = 0, axis1 = 0;
	corners(o, lo, hi);
	for (int i = 0; i < 3; i++) {
		if (rd[i] == 0) {
			if (ro[i] < lo[i] || ro[i] > hi[i])
				return;
			continue;
		}
		double a = (lo[i] - ro[i]) / rd[i], b = (hi[i] - ro[i]) / rd[i];
		if (a > b) {
			double x = a;
			a = b;
			b = x;
		}
		if (a > t0) {
			t0 = a;
			axis0 = i;
		}
		if (b < t1) {
			t1 = b;
			axis1 = i;
		}
	}
	if (t0 > t1)
		return;
	double t = t0 > tmin ? t0 : t1;
	int axis = t0 > tmin ? axis0 : axis1;
	if (!(t > tmin && t < h->t))
		return;
	h->t = t;
	memset(h->n, 0, sizeof h->n);
	h->n[axis] = (t0 > tmin) == (rd[axis] > 0) ? -1 : 1;
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	(void)s;
	double lo[3], hi[3];
	corners(o, lo, hi);
	for (int k = 0; k < 3; k++)
		if (!(p[k] > lo[k] && p[k] < hi[k]))
			return false;
	return true;
}

/* Twelve triangles wound so their normals face out (the dielectric needs to
 * know which side is inside). */
static void lower_triangles(struct lowering *lw, const scene_object *o, int mat, int id)
{
	/* corners by bits (x 1, y 2, z 4); each face in the order that makes the cross
	 * product of its first two edges point out of the box */
	static const int faces[6][4] = {
		{ 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 },
	};
	double lo[3], hi[3], corner[8][3];
	corners(o, lo, hi);
	for (int c = 0; c < 8; c++) {
		double p[3] = { c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2] };
		scene_xform_point(&o->xf, p, corner[c]);
	}
	const double (*m)[4] = o->xf.m;
	double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
	             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
	int flip = det < 0;   /* a mirroring transform turns the winding over */
	for (int f = 0; f < 6; f++) {
		const int *q = faces[f];
		int order[2][3] = { { q[0], q[1], q[2] }, { q[0], q[2], q[3] } };
		for (int t = 0; t < 2; t++) {
			double v[3][3];
			for (int k = 0; k < 3; k++)
				memcpy(v[flip ? 2 - k : k], corner[order[t][k]], sizeof v[0]);
			lower_add_triangle(lw, v, NULL, mat, id, o->loc);
		}
	}
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	const float *e = o->material.emission;
	if ((e[0] > 0 || e[1] > 0 || e[2] > 0) && !lower_in_csg(lw)) {
		lower_triangles(lw, o, mat, id);
		return 0;
	}
	double lo[3], hi[3], half[3], mid[3];
	corners(o, lo, hi);
	for (int k = 0; k < 3; k++) {
		half[k] = (hi[k] - lo[k]) / 2;
		mid[k] = (hi[k] + lo[k]) / 2;
	}
	xform unit = scene_xform_scale(half), move = scene_xform_translate(mid);
	unit = scene_xform_then(&unit, &move);
	xform to_world = scene_xform_then(&unit, &o->xf);
	dev_prim p = { .type = PRIM_BOX };
	double centre[3];
	float4 cf;
	scene_xform_point(&o->xf, mid, centre);
	if (lower_local_rows_about(&to_world, centre, &p, &cf)) {   /* flat: its faces with an area, as POV-Ray draws it */
		lower_triangles(lw, o, mat, id);
		return 0;
	}
	p.link = lower_add_data(lw, cf);
	double blo[3] = { INFINITY, INFINITY, INFINITY }, bhi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, blo, bhi);
	lower_add_prim(lw, p, mat, id, blo, bhi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fputs("box", out);
	scene_dump_vec(out, "", o->p[0]);
	scene_dump_vec(out, "", o->p[1]);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_box = {
	.name = "box", .args = "vv", .needs = "two corners",
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
