/* shape_sphere.c: sphere { <Center>, Radius }. On the device a sphere under a
 * similarity stays a sphere (kernels/shape_sphere.cl); under any other
 * transform it is an ellipsoid, kept as the map from world space to the unit
 * sphere. */
#include <math.h>

#include "lower.h"
#include "shape.h"

/* The box of the image of a ball: per axis, the row's length. */
static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	for (int k = 0; k < 3; k++) {
		double c = o->xf.m[k][0] * o->p[0][0] + o->xf.m[k][1] * o->p[0][1] + o->xf.m[k][2] * o->p[0][2] +
		           o->xf.m[k][3];
		double h = fabs(o->radius) * sqrt(o->xf.m[k][0] * o->xf.m[k][0] + o->xf.m[k][1] * o->xf.m[k][1] +
		                                  o->xf.m[k][2] * o->xf.m[k][2]);
		lo[k] = fmin(lo[k], c - h);
		hi[k] = fmax(hi[k], c + h);
	}
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	double oc[3] = { ro[0] - o->p[0][0], ro[1] - o->p[0][1], ro[2] - o->p[0][2] };
	double a = rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2];
	double b = oc[0] * rd[0] + oc[1] * rd[1] + oc[2] * rd[2];
	double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - o->radius * o->radius;
	double disc = b * b - a * c;
	if (disc < 0 || a == 0)
		return;
	for (int k = -1; k <= 1; k += 2) {
		double t = (-b + k * sqrt(disc)) / a;
		if (t > tmin && t < h->t) {
			h->t = t;
			for (int i = 0; i < 3; i++)
				h->n[i] = oc[i] + t * rd[i];
			return;
		}
	}
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	(void)s;
	double v[3] = { p[0] - o->p[0][0], p[1] - o->p[0][1], p[2] - o->p[0][2] };
	return v[0] * v[0] + v[1] * v[1] + v[2] * v[2] < o->radius * o->radius;
}

/* The uniform scale of a similarity transform, or -1 when it stretches unevenly. */
static double uniform_scale(const xform *t)
{
	double len[3], dots[3];
	for (int j = 0; j < 3; j++)
		len[j] = sqrt(t->m[0][j] * t->m[0][j] + t->m[1][j] * t->m[1][j] + t->m[2][j] * t->m[2][j]);
	for (int j = 0; j < 3; j++) {
		int k = (j + 1) % 3;
		dots[j] = t->m[0][j] * t->m[0][k] + t->m[1][j] * t->m[1][k] + t->m[2][j] * t->m[2][k];
	}
	for (int j = 0; j < 3; j++)
		if (fabs(len[j] - len[0]) > 1e-9 * len[0] || fabs(dots[j]) > 1e-9 * len[0] * len[0])
			return -1;
	return len[0];
}

/* Whether t turns (or mirrors) what it moves: its linear part is not a
 * positive multiple of the identity. */
static bool rotated(const xform *t)
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			if (i != j ? t->m[i][j] != 0 : t->m[i][i] != t->m[0][0] || !(t->m[0][0] > 0))
				return true;
	return false;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	if (!(o->radius > 0) || !isfinite(o->radius)) {
		diag_warning(o->loc, "sphere of radius %g skipped", o->radius);
		return 0;
	}
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, lo, hi);
	double scale = uniform_scale(&o->xf), c[3];
	if (scale > 0 && !(s->uv_mapped && rotated(&o->xf))) {   /* a sphere's uv turns with it */
		scene_xform_point(&o->xf, o->p[0], c);
		dev_prim p = { .a = { (float)c[0], (float)c[1], (float)c[2], (float)(o->radius * scale) },
		               .type = PRIM_SPHERE, .link = -1 };
		lower_add_prim(lw, p, mat, id, lo, hi);
		return 0;
	}
	double r[3] = { o->radius, o->radius, o->radius };
	xform unit = scene_xform_scale(r), move = scene_xform_translate(o->p[0]);
	unit = scene_xform_then(&unit, &move);
	xform to_world = scene_xform_then(&unit, &o->xf);
	dev_prim p = { .type = PRIM_ELLIPSOID, .link = -1 };
	if (lower_local_rows(&to_world, &p)) {
		diag_warning(o->loc, "sphere with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	double c[3], axis[3];
	scene_xform_point(&o->xf, o->p[0], c);
	fputs("sphere", out);
	scene_dump_vec(out, "centre", c);
	fputs(" radius ", out);
	scene_dump_num(out, o->radius);
	for (int i = 0; i < 3; i++) {   /* the images of the radius along x, y, z */
		double v[3] = { i == 0 ? o->radius : 0, i == 1 ? o->radius : 0, i == 2 ? o->radius : 0 };
		scene_xform_vector(&o->xf, v, axis);
		scene_dump_vec(out, i == 0 ? "x" : i == 1 ? "y" : "z", axis);
	}
}

const shape_class shape_sphere = {
	.name = "sphere", .args = "vf", .needs = "a centre and a radius",
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
