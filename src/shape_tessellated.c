/* shape_tessellated.c: the shapes eclat makes into triangles on the host and
 * places as it places a mesh (shape_mesh.c: once in scene.meshes, and an
 * instance of it): height_field { }, POV-Ray's grid of triangles over an
 * image (src/eval_hfield.c), and bicubic_patch { }, a Bezier patch cut into
 * 2^u_steps by 2^v_steps quadrilaterals of two triangles each, with the
 * patch's own normals at their corners (src/eval_bicubic.c), and parametric
 * { }, a grid over its (u, v) rectangle cut to its container, with POV-Ray's
 * normals at the corners (src/eval_parametric.c). o->mesh is the
 * mesh, or -1 when --skip-unsupported left it out. */
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

/* POV-Ray's HField::Inside: below the surface over its square, which is one
 * crossing upward. */
static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	double d[3];
	return shape_mesh_inside_dir(s, o, d) == 0 && shape_mesh_crossings(s, o, p, d) % 2 == 1;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	return o->mesh >= 0 ? lower_mesh_instance(lw, s, o, mat, id) : 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "%s mesh %d", shape_of(o)->name, o->mesh);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_height_field = {
	.name = AST_WORD_HEIGHT_FIELD, .args = NULL, .needs = "an image or a function",
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};

const shape_class shape_parametric = {
	.name = AST_WORD_PARAMETRIC, .args = NULL, .needs = "three functions and a range of u and v",
	.bounds = bounds, .trace = trace, .lower = lower, .dump = dump,
};

const shape_class shape_bicubic_patch = {
	.name = AST_WORD_BICUBIC_PATCH, .args = NULL, .needs = "16 control points",
	.bounds = bounds, .trace = trace, .lower = lower, .dump = dump,
};
