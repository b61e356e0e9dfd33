/* shape_text.c: text { ttf "Font" "String" Thickness, <Offset> }: POV-Ray's, the
 * glyphs read with FreeType and flattened into edges by src/eval_outline.c,
 * drawn by src/prism.c, each glyph a primitive of its own (all in one in CSG). */
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
	fprintf(out, "text outline %d thickness ", o->outline);
	scene_dump_num(out, o->radius);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_text = {
	.name = "text", .args = NULL, .needs = "a font, a string, a thickness and an offset",
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
