/* shape_height_field.c: height_field { }, POV-Ray's height field: src/eval_hfield.c
 * makes it the mesh of triangles POV-Ray intersects, and it is placed as any
 * mesh is (shape_mesh.c): once in scene.meshes, and an instance of it. */
#include "ast.h"
#include "lower.h"
#include "shape.h"

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	if (o->mesh >= 0)
		shape_mesh.bounds(s, o, lo, hi);
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	if (o->mesh >= 0)
		shape_mesh.trace(s, o, ro, rd, tmin, h);
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	return o->mesh >= 0 ? lower_mesh_instance(lw, s, o, mat, id) : 0;   /* < 0: --skip-unsupported */
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "height_field mesh %d", o->mesh);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_height_field = {
	.name = AST_WORD_HEIGHT_FIELD, .args = NULL, .needs = "an image or a function",
	.bounds = bounds, .trace = trace, .lower = lower, .dump = dump,
};
