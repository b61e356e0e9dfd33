/* shape_sor.c: sor { Number, <P0>, <P1>, ... [open] [sturm] }: POV-Ray's surface
 * of revolution, a cubic interpolating spline of the squared radius against
 * the height revolved about y (src/revolve.h); the first and last points only
 * steer the curve; caps at both ends unless open. */
#include "revolve.h"

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "sor%s outline %d", o->shape_flags & SHAPE_OPEN ? " open" : "", o->outline);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_sor = {
	.name = "sor", .args = NULL, .needs = "a count and its points", .flags = SHAPE_OPEN | SHAPE_STURM,
	.bounds = revolve_shape_bounds, .trace = revolve_shape_trace, .inside = revolve_shape_inside,
	.lower = revolve_shape_lower, .dump = dump,
};
