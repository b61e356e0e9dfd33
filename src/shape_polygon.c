/* shape_polygon.c: polygon { Number, <Point1>, <Point2>... }: POV-Ray's, its
 * points in a plane, read by src/eval_outline.c and drawn by src/prism.c as a
 * prism of one flat face. It has no inside. */
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

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	prism_view v = prism_view_of(s, o);
	return prism_lower(lw, &v, o, mat, id);
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "polygon outline %d", o->outline);
	scene_dump_vec(out, "origin", o->p[0]);
	scene_dump_vec(out, "normal", o->n[1]);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_polygon = {
	.name = "polygon", .args = NULL, .needs = "a count and its points",
	.bounds = bounds, .trace = trace, .lower = lower, .dump = dump,
};
