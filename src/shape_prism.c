/* shape_prism.c: prism { [SWEEP] [SPLINE] Height1, Height2, Number, <Point>... [open] }:
 * POV-Ray's prism, its splines flattened into edges when it is read
 * (src/eval_outline.c), drawn by src/prism.c. */
#include "prism.h"

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	prism_view v = prism_view_of(s, o);
	prism_bounds(&v, &o->xf, lo, hi);
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	prism_view v = prism_view_of(s, o);
	prism_trace(&v, ro, rd, tmin, h);
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	prism_view v = prism_view_of(s, o);
	return prism_inside(&v, p);
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	prism_view v = prism_view_of(s, o);
	return prism_lower(lw, &v, o, mat, id);
}

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
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
