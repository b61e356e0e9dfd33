/* shape_disc.c: disc { <Center>, <Normal>, Radius [, Hole_Radius] }, as
 * POV-Ray 3.7's disc.cpp makes it: the points of the plane through Center
 * perpendicular to Normal whose distance from Center is between Hole_Radius
 * and Radius, both included. Its inside is the half-space behind it, away from
 * Normal, as for a plane. POV-Ray squares both radii, so their signs do not
 * matter. On the device (kernels/shape_disc.cl) it is the unit disc in z = 0,
 * the primitive's rows the map from world space to it about its centre, and
 * its PRIM_DATA records the square of the hole's radius over the disc's, then
 * the centre. A disc of radius 0, or with
 * a normal of length 0, draws nothing in POV-Ray; lowering leaves it out with
 * a warning. */
#include <math.h>
#include <stdbool.h>

#include "lower.h"
#include "shape.h"

#define SMALL_TOLERANCE 0.001   /* POV-Ray's: the thickness of its box */

/* The unit normal; false when it has length 0 (POV-Ray's is then not a number). */
static bool unit_normal(const scene_object *o, double n[3])
{
	double len = sqrt(o->p[1][0] * o->p[1][0] + o->p[1][1] * o->p[1][1] + o->p[1][2] * o->p[1][2]);
	for (int k = 0; k < 3; k++)
		n[k] = len > 0 ? o->p[1][k] / len : 0;
	return len > 0 && isfinite(len);
}

/* POV-Ray's space of the disc: unscaled, z along the normal, the centre at the
 * origin (Compute_Disc). */
static bool disc_space(const scene_object *o, xform *to_object)
{
	double n[3];
	if (!unit_normal(o, n))
		return false;
	*to_object = shape_coordinate_xform(o->p[0], n, 1, 1);
	return true;
}

/* POV-Ray's box: the disc's square, SMALL_TOLERANCE thick. */
static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	xform t;
	if (!disc_space(o, &t))
		return;
	double r = fabs(o->radius), a[3] = { -r, -r, -SMALL_TOLERANCE }, b[3] = { r, r, SMALL_TOLERANCE };
	xform to_world = scene_xform_then(&t, &o->xf);
	shape_grow_xformed_box(&to_world, a, b, lo, hi);
}

/* POV-Ray's Disc::Intersect in double precision, in object space. */
static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	double n[3];
	if (!unit_normal(o, n))
		return;
	double dn = n[0] * rd[0] + n[1] * rd[1] + n[2] * rd[2];
	double len = sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2]);
	if (!(fabs(dn) > 1e-10 * len))   /* POV-Ray's EPSILON, on the unit direction */
		return;
	double v[3] = { ro[0] - o->p[0][0], ro[1] - o->p[0][1], ro[2] - o->p[0][2] };
	double t = -(n[0] * v[0] + n[1] * v[1] + n[2] * v[2]) / dn;
	if (!(t > tmin && t < h->t))
		return;
	double r2 = 0;
	for (int k = 0; k < 3; k++) {
		double w = v[k] + t * rd[k];
		r2 += w * w;
	}
	if (!(r2 >= o->param[0] * o->param[0] && r2 <= o->radius * o->radius))
		return;
	h->t = t;
	for (int k = 0; k < 3; k++)
		h->n[k] = n[k];
}

/* POV-Ray's Disc::Inside: behind the disc's plane, however far from the disc. */
static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	(void)s;
	double n[3];
	if (!unit_normal(o, n))
		return false;
	return n[0] * (p[0] - o->p[0][0]) + n[1] * (p[1] - o->p[0][1]) + n[2] * (p[2] - o->p[0][2]) < 0;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	double n[3], r = fabs(o->radius);
	if (!unit_normal(o, n)) {
		diag_warning(o->loc, "disc with a normal of length 0 skipped");
		return 0;
	}
	if (!(r > 0)) {
		diag_warning(o->loc, "disc of radius 0 skipped");
		return 0;
	}
	xform unit = shape_coordinate_xform(o->p[0], n, r, r), to_world = scene_xform_then(&unit, &o->xf);
	dev_prim p = { .type = PRIM_DISC };
	double centre[3];
	float4 cf;
	scene_xform_point(&o->xf, o->p[0], centre);
	if (lower_local_rows_about(&to_world, centre, &p, &cf)) {
		diag_warning(o->loc, "disc with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	double hole = o->param[0] / r;
	p.link = lower_add_data(lw, (float4){ (float)(hole * hole), 0, 0, 0 });
	lower_add_data(lw, cf);   /* the next record: the centre */
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fputs("disc", out);
	scene_dump_vec(out, "centre", o->p[0]);
	scene_dump_vec(out, "normal", o->p[1]);
	fputs(" radius ", out);
	scene_dump_num(out, o->radius);
	if (o->param[0] != 0) {
		fputs(" hole ", out);
		scene_dump_num(out, o->param[0]);
	}
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_disc = {
	.name = "disc", .args = "vvf|f", .needs = "a centre, a normal and a radius",
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
