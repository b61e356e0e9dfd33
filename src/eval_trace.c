/* eval_trace.c: POV-Ray's trace() and inside() on the host, while the scene is
 * evaluated.
 *
 *   trace(OBJECT, <Start>, <Direction> [, NORMAL_IDENTIFIER])
 *
 * gives the first point where the ray from Start along Direction meets the
 * object, and sets the identifier to the object's unit normal there; with no hit
 * both are <0, 0, 0>, as in POV-Ray. Scenes use it to put things on surfaces.
 * Each shape of the object is hit in its own object space (the ray taken there
 * by the inverse of its transform, which keeps the ray's parameter) by its
 * class's trace (src/shape.h).
 *
 *   inside(OBJECT, <Point>)
 *
 * is 1 where the point is inside the object (any of its shapes; a CSG object
 * by its program over its leaves' inside tests, as kernels/csg.cl), else 0. */
#include <math.h>
#include <string.h>

#include "eval_int.h"
#include "shape.h"
#include "csg.h"
#include "vec3.h"

/* The nearest hit of one shape with tmin < t < h->t: h gets t and the world normal. */
static void trace_shape(const scene *sc, const scene_object *s, const double o[3], const double d[3], double tmin,
                        shape_hit *h)
{
	xform inv = eval_xform_inverse(&s->xf);
	double lo[3], ld[3];
	scene_xform_point(&inv, o, lo);
	scene_xform_vector(&inv, d, ld);
	shape_hit l = { .t = h->t };
	shape_of(s)->trace(sc, s, lo, ld, tmin, &l);
	if (l.t >= h->t)
		return;
	h->t = l.t;
	/* normals go to world space by the inverse's transpose */
	for (int k = 0; k < 3; k++)
		h->n[k] = inv.m[0][k] * l.n[0] + inv.m[1][k] * l.n[1] + inv.m[2][k] * l.n[2];
}

struct leaves {
	const scene *sc;
	const scene_object *leaf;   /* the CSG object's first */
	double x[3];                /* the point in world space */
};

static bool leaf_inside(void *ctx, int k)
{
	const struct leaves *c = ctx;
	if (k >= CSG_NO_LEAF)
		return false;
	const scene_object *s = &c->leaf[k];
	xform inv = eval_xform_inverse(&s->xf);
	double p[3];
	scene_xform_point(&inv, c->x, p);
	return shape_of(s)->inside && shape_of(s)->inside(c->sc, s, p);
}

/* Whether a leaf offers a CSG only its nearest hit: a mesh with no inside,
 * a parametric, a bicubic patch (shape.h, shape_mesh_inside_dir). */
static bool nearest_only(const scene *sc, const scene_object *s)
{
	double d[3];
	bool meshed = s->shape == SHAPE_MESH || s->shape == SHAPE_PARAMETRIC || s->shape == SHAPE_BICUBIC_PATCH;
	return meshed && shape_mesh_inside_dir(sc, s, d) < 0;
}

/* A CSG object's nearest surface point, as kernels/csg.cl finds it: its
 * leaves' hits one after another, each kept when the program says the CSG's
 * surface is there. */
static void trace_csg(const scene *sc, const struct objval *obj, const struct objcsg *g, const double o[3],
                      const double d[3], shape_hit *out)
{
	struct leaves c = { sc, &obj->objs[g->first], { 0, 0, 0 } };
	double t = SHAPE_TRACE_EPSILON;
	for (int crossing = 0; crossing < 256; crossing++) {   /* as kernels/csg.cl */
		shape_hit h = { .t = out->t };
		int which = -1;
		for (int k = 0; k < g->n_leaves; k++) {
			if (c.leaf[k].clip)
				continue;   /* clipped_by's leaves are never seen */
			double before = h.t;
			if (nearest_only(sc, &c.leaf[k])) {   /* kernels/csg_mesh.cl */
				shape_hit n = { .t = h.t };
				trace_shape(sc, &c.leaf[k], o, d, SHAPE_TRACE_EPSILON, &n);
				if (n.t < h.t && n.t > t)
					h = n;
			} else {
				trace_shape(sc, &c.leaf[k], o, d, t, &h);
			}
			which = h.t < before ? k : which;
		}
		if (which < 0)
			return;
		for (int k = 0; k < 3; k++)
			c.x[k] = o[k] + h.t * d[k];
		bool flip;
		if (csg_classify(g->ops, g->n_ops, which, leaf_inside, &c, &flip)) {
			out->t = h.t;
			for (int k = 0; k < 3; k++)
				out->n[k] = flip ? -h.n[k] : h.n[k];
			return;
		}
		t = h.t;
	}
}

/* The CSG object whose first leaf is the object's shape i, or NULL. */
static const struct objcsg *csg_at(const struct objval *obj, int i)
{
	for (int k = 0; k < obj->n_csgs; k++)
		if (obj->csgs[k].first == i)
			return &obj->csgs[k];
	return NULL;
}

/* The nearest hit of the object's shapes and CSG objects: 1 and the world
 * point and unit normal, or 0. */
static int trace_object(const scene *sc, const struct objval *obj, const double o[3], const double d[3],
                        double point[3], double normal[3])
{
	shape_hit h = { .t = INFINITY };
	for (int i = 0; i < obj->n_objs;) {
		const struct objcsg *g = csg_at(obj, i);
		if (g) {
			trace_csg(sc, obj, g, o, d, &h);
			i += g->n_leaves;
		} else {
			trace_shape(sc, &obj->objs[i], o, d, SHAPE_TRACE_EPSILON, &h);
			i++;
		}
	}
	if (h.t == INFINITY)
		return 0;
	double len = sqrt(vec3_dot(h.n, h.n));
	for (int k = 0; k < 3; k++) {
		point[k] = o[k] + h.t * d[k];
		normal[k] = (len > 0 ? h.n[k] / len : 0) + 0.0;   /* no -0 */
	}
	return 1;
}

/* The same object read for both functions: the object, or -1 after an error. */
static int object_arg(struct eval *e, const ast_node *n, const char *fn, value *v)
{
	if (AST_IS_EXPRESSION(n->kind) ? eval_expect_kind(e, n, V_OBJECT, v) : eval_block_value(e, n, v))
		return -1;
	if (v->kind != V_OBJECT) {
		eval_error(e, n->loc, "%s() needs an object, not %s", fn, eval_kind_name(v->kind));
		eval_value_free(v);
		return -1;
	}
	return 0;
}

/* 0 when the host can trace obj: not when an isosurface's function calls the
 * scene's patterns, which only the device evaluates. Then an error, or with
 * --skip-unsupported a warning and 1: trace() misses, inside() is false. */
static int host_traceable(struct eval *e, const struct objval *obj, const ast_node *n)
{
	for (int i = 0; i < obj->n_objs; i++)
		if (obj->objs[i].shape == SHAPE_ISOSURFACE && scene_function_calls_patterns(e->s, obj->objs[i].function)) {
			const char *fn = ast_keyword_name(n->kw);
			if (!e->opt->skip_unsupported) {
				eval_error(e, n->kids[0]->loc, "%s() of an isosurface whose function calls a pattern or pigment "
				           "function, which only the device evaluates", fn);
				return -1;
			}
			eval_warn_once(e, n->loc, "trace of pattern isosurface", "%s() of an isosurface whose function "
			               "calls a pattern or pigment function, which only the device evaluates: it misses", fn);
			return 1;
		}
	return 0;
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
	if (object_arg(e, n->kids[0], "trace", &v))
		return -1;
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
	int host = host_traceable(e, v.obj, n);
	if (host < 0) {
		eval_value_free(&v);
		return -1;
	}
	if (host > 0 || !trace_object(e->s, v.obj, o, d, point, normal))
		memset(normal, 0, sizeof normal);
	eval_value_free(&v);
	if (n->n_kids == 4)
		eval_assign(e, n->kids[3]->str, eval_vector3(normal), false);
	*out = eval_vector3(point);
	return 0;
}

int eval_inside(struct eval *e, const ast_node *n, value *out)
{
	if (n->n_kids != 2) {
		eval_error(e, n->loc, "inside() takes an object and a point");
		return -1;
	}
	value v;
	double p[3];
	if (object_arg(e, n->kids[0], "inside", &v))
		return -1;
	if (eval_expect_vector(e, n->kids[1], p)) {
		eval_value_free(&v);
		return -1;
	}
	if (v.obj->unsupported && !e->opt->skip_unsupported) {
		eval_error(e, n->kids[0]->loc, "inside() of a '%s', which is not supported yet", v.obj->unsupported);
		eval_value_free(&v);
		return -1;
	}
	const struct objval *obj = v.obj;
	int host = host_traceable(e, obj, n);
	if (host < 0) {
		eval_value_free(&v);
		return -1;
	}
	bool in = false;
	for (int i = 0; host == 0 && i < obj->n_objs && !in;) {
		const struct objcsg *g = csg_at(obj, i);
		struct leaves c = { e->s, &obj->objs[i], { p[0], p[1], p[2] } };
		if (g) {
			in = csg_inside(g->ops, g->n_ops, leaf_inside, &c);
			i += g->n_leaves;
		} else {
			in = !obj->objs[i].clip && leaf_inside(&c, 0);
			i++;
		}
	}
	eval_value_free(&v);
	*out = eval_float(in ? 1 : 0);
	return 0;
}
