/* shape_lathe.c: lathe { [linear_spline | quadratic_spline | cubic_spline |
 * bezier_spline] Number, <P0>, ... [sturm] }: POV-Ray's lathe, the 2D spline
 * (x the radius, y the height) revolved about y (src/revolve.h). */
#include "revolve.h"

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "lathe%s outline %d", (const char *[]){ " linear_spline", " quadratic_spline", " cubic_spline", " bezier_spline" }[(int)o->param[0] & 3], o->outline);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_lathe = {
	.name = "lathe", .args = NULL, .needs = "a count and its points", .flags = SHAPE_STURM,
	.bounds = revolve_shape_bounds, .trace = revolve_shape_trace, .inside = revolve_shape_inside,
	.lower = revolve_shape_lower, .dump = dump,
};
