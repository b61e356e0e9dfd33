/* eval_trace.c: POV-Ray's trace() on the host, while the scene is evaluated.
 *
 *   trace(OBJECT, <Start>, <Direction> [, NORMAL_IDENTIFIER])
 *
 * gives the first point where the ray from Start along Direction meets the
 * object, and sets the identifier to the object's unit normal there; with no hit
 * both are <0, 0, 0>, as in POV-Ray. Scenes use it to put things on surfaces.
 * Each shape of the object is hit in its own object space (the ray taken there
 * by the inverse of its transform, which keeps the ray's parameter) by its
 * class's trace (src/shape.h). */
#include <math.h>
#include <string.h>

#include "eval_int.h"
#include "shape.h"

static double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The nearest hit of the object's shapes: 1 and the world point and unit normal,
 * or 0. */
static int trace_object(const scene *sc, const struct objval *obj, const double o[3], const double d[3],
                        double point[3], double normal[3])
{
	double best = INFINITY;
	for (int i = 0; i < obj->n_objs; i++) {
		const scene_object *s = &obj->objs[i];
		xform inv = eval_xform_inverse(&s->xf);
		double lo[3], ld[3];
		scene_xform_point(&inv, o, lo);
		scene_xform_vector(&inv, d, ld);
		shape_hit h = { .t = best };
		shape_of(s)->trace(sc, s, lo, ld, SHAPE_TRACE_EPSILON, &h);
		if (h.t >= best)
			continue;
		best = h.t;
		/* normals go to world space by the inverse's transpose */
		for (int k = 0; k < 3; k++)
			normal[k] = inv.m[0][k] * h.n[0] + inv.m[1][k] * h.n[1] + inv.m[2][k] * h.n[2];
	}
	if (best == INFINITY)
		return 0;
	double len = sqrt(dot3(normal, normal));
	for (int k = 0; k < 3; k++) {
		point[k] = o[k] + best * d[k];
		normal[k] = (len > 0 ? normal[k] / len : 0) + 0.0;   /* no -0 */
	}
	return 1;
}

int eval_trace(struct eval *e, const ast_node *n, value *out)
{
	if (n->n_kids < 3 || n->n_kids > 4) {
		eval_error(e, n->loc, "trace() takes an object, a start, a direction and a normal identifier");
		return -1;
	}
	if (n->n_kids == 4 && n->kids[3]->kind != AST_IDENT) {
		eval_error(e, n->kids[3]->loc, "trace()'s fourth argument is the identifier that gets the normal");
		return -1;
	}
	value v;
	double o[3], d[3], point[3] = { 0, 0, 0 }, normal[3] = { 0, 0, 0 };
	if (AST_IS_EXPRESSION(n->kids[0]->kind) ? eval_expect_kind(e, n->kids[0], V_OBJECT, &v)
	                                         : eval_block_value(e, n->kids[0], &v))
		return -1;
	if (v.kind != V_OBJECT) {
		eval_error(e, n->kids[0]->loc, "trace() needs an object, not %s", eval_kind_name(v.kind));
		eval_value_free(&v);
		return -1;
	}
	if (eval_expect_vector(e, n->kids[1], o) || eval_expect_vector(e, n->kids[2], d)) {
		eval_value_free(&v);
		return -1;
	}
	if (v.obj->unsupported) {
		if (!e->opt->skip_unsupported) {
			eval_error(e, n->kids[0]->loc, "trace() of a '%s', which is not supported yet", v.obj->unsupported);
			eval_value_free(&v);
			return -1;
		}
		eval_warn_once(e, n->loc, "trace of unsupported", "trace() misses the '%s', which eclat leaves out",
		               v.obj->unsupported);
	}
	if (!trace_object(e->s, v.obj, o, d, point, normal))
		memset(normal, 0, sizeof normal);
	eval_value_free(&v);
	if (n->n_kids == 4)
		eval_assign(e, n->kids[3]->str, eval_vector3(normal), false);
	*out = eval_vector3(point);
	return 0;
}
