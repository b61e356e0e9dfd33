/* shape_sor.c: sor { Number, <P0>, <P1>, ... [open] [sturm] }: POV-Ray's surface
 * of revolution, a cubic interpolating spline of the squared radius against
 * the height revolved about y (src/revolve.h); the first and last points only
 * steer the curve; caps at both ends unless open. */
#include "revolve.h"

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	revolve_profile pr;
	if (!revolve_profile_of(s, o, &pr))
		revolve_bounds(&pr, &o->xf, lo, hi);
	revolve_free(&pr);
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	revolve_profile pr;
	if (!revolve_profile_of(s, o, &pr))
		revolve_trace(&pr, ro, rd, tmin, h);
	revolve_free(&pr);
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	revolve_profile pr;
	bool in = !revolve_profile_of(s, o, &pr) && revolve_inside(&pr, p);
	revolve_free(&pr);
	return in;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	revolve_profile pr;
	const char *bad = revolve_profile_of(s, o, &pr);
	int rc = 0;
	if (bad) {
		diag_error(o->loc, "%s", bad);
		rc = -1;
	} else {
		rc = revolve_lower(lw, &pr, o, mat, id);
	}
	revolve_free(&pr);
	return rc;
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "sor%s outline %d", o->shape_flags & SHAPE_OPEN ? " open" : "", o->outline);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_sor = {
	.name = "sor", .args = NULL, .needs = "a count and its points", .flags = SHAPE_OPEN | SHAPE_STURM,
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
