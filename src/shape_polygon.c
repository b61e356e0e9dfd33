/* shape_polygon.c: polygon { Number, <Point1>, <Point2>... }: POV-Ray's, its
 * points in a plane, read by src/eval_outline.c and drawn by src/prism.c as a
 * prism of one flat face. It has no inside. */
#include "prism.h"

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "polygon outline %d", o->outline);
	scene_dump_vec(out, "origin", o->p[0]);
	scene_dump_vec(out, "normal", o->n[1]);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_polygon = {
	.name = "polygon", .args = NULL, .needs = "a count and its points",
	.bounds = prism_shape_bounds, .trace = prism_shape_trace, .lower = prism_shape_lower, .dump = dump,
};
