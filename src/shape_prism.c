/* shape_prism.c: prism { [SWEEP] [SPLINE] Height1, Height2, Number, <Point>... [open] }:
 * POV-Ray's prism, its splines flattened into edges when it is read
 * (src/eval_outline.c), drawn by src/prism.c. */
#include "prism.h"

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "prism%s%s outline %d heights ", o->param[1] != 0 ? " conic_sweep" : "",
	        o->shape_flags & SHAPE_OPEN ? " open" : "", o->outline);
	scene_dump_num(out, o->radius);
	fputs(" ", out);
	scene_dump_num(out, o->param[0]);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_prism = {
	.name = "prism", .args = NULL, .needs = "two heights, a count and its points", .flags = SHAPE_OPEN | SHAPE_STURM,
	.bounds = prism_shape_bounds, .trace = prism_shape_trace, .inside = prism_shape_inside,
	.lower = prism_shape_lower, .dump = dump,
};
