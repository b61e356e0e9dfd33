/* shape_torus.c: torus { Major, Minor [sturm] }, POV-Ray's torus: the points
 * at the distance Minor from the circle of radius Major around the y axis in
 * the xz plane. A minor radius larger than the major one makes POV-Ray 3.7's
 * spindle torus: every root of the quartic is a surface, the spindle inside
 * included, and the inside is the union of the balls of radius Minor around
 * the circle. POV-Ray's sturm picks its slower, surer root finder; eclat's
 * (src/roots.c, kernels/roots.cl) loses no root but where a ray only touches
 * the surface, so sturm is read and changes nothing.
 *
 * On the device a torus is the map from world space to the torus of major
 * radius 1 (kernels/shape_torus.cl), with Minor / Major in its PRIM_DATA record. */
#include <math.h>

#include "ast.h"
#include "lower.h"
#include "roots.h"
#include "shape.h"

#define MAJOR(o) ((o)->radius)
#define MINOR(o) ((o)->param[0])

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	double r = fabs(MINOR(o)), big = fabs(MAJOR(o)) + r;
	double a[3] = { -big, -r, -big }, b[3] = { big, r, big };
	shape_grow_xformed_box(&o->xf, a, b, lo, hi);
}

/* ---- the shape ---- */

/* The nearest hit, as POV-Ray finds it (torus.cpp): the ray with a unit
 * direction, its start moved to the bounding sphere, and the quartic in the
 * distance from there; here only its roots inside the sphere are looked for. */
static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	double R = MAJOR(o), r = MINOR(o);
	double len = sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2]);
	if (!(len > 0) || !(R > 0) || !(r > 0))
		return;
	double D[3] = { rd[0] / len, rd[1] / len, rd[2] / len }, P[3] = { ro[0], ro[1], ro[2] };
	double B = (R + r) * (1 + 1e-9), b = P[0] * D[0] + P[1] * D[1] + P[2] * D[2], f[3];
	for (int k = 0; k < 3; k++)
		f[k] = P[k] - b * D[k];   /* the closest point to the centre keeps precision */
	double disc = B * B - (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
	if (disc < 0)
		return;
	double s0 = fmax(-b - sqrt(disc), tmin * len), s1 = fmin(-b + sqrt(disc), h->t * len);
	if (!(s0 < s1))
		return;
	for (int k = 0; k < 3; k++)
		P[k] += s0 * D[k];
	double R2 = R * R, r2 = r * r, Py2 = P[1] * P[1], PDy = P[1] * D[1];
	double k1 = P[0] * P[0] + P[2] * P[2] + Py2 - R2 - r2, k2 = P[0] * D[0] + P[2] * D[2] + PDy;
	double c[5] = { k1 * k1 + 4 * R2 * (Py2 - r2), 4 * (k2 * k1 + 2 * R2 * PDy),
	                2 * (k1 + 2 * (k2 * k2 + R2 * D[1] * D[1])), 4 * k2, 1 };
	double u[1];
	if (roots_find(c, 4, 0, s1 - s0, u, 1) == 0)
		return;
	double t = (s0 + u[0]) / len;
	if (!(t > tmin && t < h->t))
		return;
	h->t = t;
	/* POV-Ray's normal: from the nearest point of the circle */
	double x[3] = { ro[0] + t * rd[0], ro[1] + t * rd[1], ro[2] + t * rd[2] };
	double rho = sqrt(x[0] * x[0] + x[2] * x[2]);
	h->n[0] = rho > 1e-10 ? x[0] - R * x[0] / rho : x[0];
	h->n[1] = x[1];
	h->n[2] = rho > 1e-10 ? x[2] - R * x[2] / rho : x[2];
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	(void)s;
	double rho = sqrt(p[0] * p[0] + p[2] * p[2]) - MAJOR(o);
	return rho * rho + p[1] * p[1] <= MINOR(o) * MINOR(o);
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	double R = MAJOR(o), r = MINOR(o);
	if (!(R > 0) || !(r > 0) || !isfinite(R) || !isfinite(r)) {
		diag_warning(o->loc, "torus of radii %g and %g skipped: both must be above 0", R, r);
		return 0;
	}
	double scale[3] = { R, R, R };
	xform unit = scene_xform_scale(scale), to_world = scene_xform_then(&unit, &o->xf);
	dev_prim p = { .type = PRIM_TORUS };
	if (lower_local_rows(&to_world, &p)) {
		diag_warning(o->loc, "torus with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	p.link = lower_add_data(lw, (float4){ (float)(r / R), 0, 0, 0 });
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fputs("torus major ", out);
	scene_dump_num(out, MAJOR(o));
	fputs(" minor ", out);
	scene_dump_num(out, MINOR(o));
	if (o->shape_flags & SHAPE_STURM)
		fputs(" sturm", out);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_torus = {
	.name = AST_WORD_TORUS, .args = "ff", .needs = "a major and a minor radius", .flags = SHAPE_STURM,
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
