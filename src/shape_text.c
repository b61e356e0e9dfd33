/* shape_text.c: text { ttf "Font" "String" Thickness, <Offset> }: POV-Ray's, the
 * glyphs read with FreeType and flattened into edges by src/eval_outline.c,
 * drawn by src/prism.c, each glyph a primitive of its own (all in one in CSG). */
#include "prism.h"

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "text outline %d thickness ", o->outline);
	scene_dump_num(out, o->radius);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_text = {
	.name = "text", .args = NULL, .needs = "a font, a string, a thickness and an offset",
	.bounds = prism_shape_bounds, .trace = prism_shape_trace, .inside = prism_shape_inside,
	.lower = prism_shape_lower, .dump = dump,
};
