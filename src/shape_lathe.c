/* shape_lathe.c: lathe { [linear_spline | quadratic_spline | cubic_spline |
 * bezier_spline] Number, <P0>, ... [sturm] }: POV-Ray's lathe, the 2D spline
 * (x the radius, y the height) revolved about y (src/revolve.h). */
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
	fprintf(out, "lathe%s outline %d", (const char *[]){ " linear_spline", " quadratic_spline", " cubic_spline", " bezier_spline" }[(int)o->param[0] & 3], o->outline);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_lathe = {
	.name = "lathe", .args = NULL, .needs = "a count and its points", .flags = SHAPE_STURM,
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
