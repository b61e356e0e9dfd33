/* shape_plane.c: plane { <Normal>, Distance }: the points p with
 * p . n = Distance, n unit length; its inside is the half-space below. Planes
 * are unbounded: lowering keeps them out of the BVH (kernels/shape_plane.cl). */
#include <math.h>

#include "lower.h"
#include "shape.h"

static double unit_normal(const scene_object *o, double n[3])
{
	double len = sqrt(o->p[0][0] * o->p[0][0] + o->p[0][1] * o->p[0][1] + o->p[0][2] * o->p[0][2]);
	for (int i = 0; i < 3; i++)
		n[i] = len > 0 ? o->p[0][i] / len : 0;
	return len;
}

static const char *check(const scene_object *o)
{
	double n[3];
	return unit_normal(o, n) > 0 ? NULL : "a plane needs a normal that is not zero";
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	double n[3];
	if (unit_normal(o, n) == 0)
		return;
	double dn = n[0] * rd[0] + n[1] * rd[1] + n[2] * rd[2];
	if (dn == 0)
		return;
	double t = (o->radius - (n[0] * ro[0] + n[1] * ro[1] + n[2] * ro[2])) / dn;
	if (t > tmin && t < h->t) {
		h->t = t;
		for (int i = 0; i < 3; i++)
			h->n[i] = n[i];
	}
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	(void)s;
	double n[3];
	unit_normal(o, n);
	return n[0] * p[0] + n[1] * p[1] + n[2] * p[2] < o->radius;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	(void)s;
	double n[3];
	xform inv;
	if (unit_normal(o, n) == 0) {
		diag_error(o->loc, "a plane needs a normal that is not zero");
		return -1;
	}
	if (lower_invert(&o->xf, &inv)) {
		diag_warning(o->loc, "plane with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	double p0[3] = { n[0] * o->radius, n[1] * o->radius, n[2] * o->radius }, w[3], wn[3];
	scene_xform_point(&o->xf, p0, w);
	for (int i = 0; i < 3; i++)   /* normals map by the transposed inverse */
		wn[i] = inv.m[0][i] * n[0] + inv.m[1][i] * n[1] + inv.m[2][i] * n[2];
	double wl = sqrt(wn[0] * wn[0] + wn[1] * wn[1] + wn[2] * wn[2]);
	for (int i = 0; i < 3; i++)
		wn[i] /= wl;
	dev_prim p = { .a = { (float)wn[0], (float)wn[1], (float)wn[2], (float)(wn[0] * w[0] + wn[1] * w[1] + wn[2] * w[2]) },
	               .type = PRIM_PLANE, .link = -1 };
	lower_add_prim(lw, p, mat, id, NULL, NULL);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fputs("plane", out);
	scene_dump_vec(out, "normal", o->p[0]);
	fputs(" distance ", out);
	scene_dump_num(out, o->radius);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_plane = {
	.name = "plane", .args = "vf", .needs = "a normal and a distance",
	.check = check, .bounds = shape_unbounded, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
