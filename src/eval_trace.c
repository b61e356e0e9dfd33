/* eval_trace.c: POV-Ray's trace() on the host, while the scene is evaluated.
 *
 *   trace(OBJECT, <Start>, <Direction> [, NORMAL_IDENTIFIER])
 *
 * gives the first point where the ray from Start along Direction meets the
 * object, and sets the identifier to the object's unit normal there; with no hit
 * both are <0, 0, 0>, as in POV-Ray. Scenes use it to put things on surfaces.
 * Each shape of the object is hit in its own object space (the ray taken there
 * by the inverse of its transform, which keeps the ray's parameter), a mesh face
 * by face: a scene calls trace() a few thousand times at most, so no BVH. */
#include <math.h>
#include <string.h>

#include "eval_int.h"

#define TRACE_EPSILON 1e-9   /* hits nearer the start than this are the start's own surface */

struct trace_hit {
	double t;
	double n[3];   /* object space */
};

static double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
	out[0] = a[1] * b[2] - a[2] * b[1];
	out[1] = a[2] * b[0] - a[0] * b[2];
	out[2] = a[0] * b[1] - a[1] * b[0];
}

static void keep(struct trace_hit *h, double t, const double n[3])
{
	if (t > TRACE_EPSILON && t < h->t) {
		h->t = t;
		memcpy(h->n, n, sizeof h->n);
	}
}

static void sphere(const scene_object *s, const double o[3], const double d[3], struct trace_hit *h)
{
	double oc[3] = { o[0] - s->p[0][0], o[1] - s->p[0][1], o[2] - s->p[0][2] };
	double a = dot3(d, d), b = dot3(oc, d), c = dot3(oc, oc) - s->radius * s->radius;
	double disc = b * b - a * c;
	if (disc < 0 || a == 0)
		return;
	for (int k = -1; k <= 1; k += 2) {
		double t = (-b + k * sqrt(disc)) / a, n[3];
		for (int i = 0; i < 3; i++)
			n[i] = oc[i] + t * d[i];
		keep(h, t, n);
	}
}

/* The slabs of the box: the entering face, or the leaving one from inside. */
static void box(const scene_object *s, const double o[3], const double d[3], struct trace_hit *h)
{
	double t0 = -INFINITY, t1 = INFINITY;
	int axis0 = 0, axis1 = 0;
	for (int i = 0; i < 3; i++) {
		double lo = fmin(s->p[0][i], s->p[1][i]), hi = fmax(s->p[0][i], s->p[1][i]);
		if (d[i] == 0) {
			if (o[i] < lo || o[i] > hi)
				return;
			continue;
		}
		double a = (lo - o[i]) / d[i], b = (hi - o[i]) / d[i];
		if (a > b) {
			double x = a;
			a = b;
			b = x;
		}
		if (a > t0) {
			t0 = a;
			axis0 = i;
		}
		if (b < t1) {
			t1 = b;
			axis1 = i;
		}
	}
	if (t0 > t1)
		return;
	double n0[3] = { 0, 0, 0 }, n1[3] = { 0, 0, 0 };
	n0[axis0] = d[axis0] > 0 ? -1 : 1;
	n1[axis1] = d[axis1] > 0 ? 1 : -1;
	keep(h, t0, n0);
	keep(h, t1, n1);
}

/* POV-Ray's plane: the points at Distance along the unit normal (lower.c too). */
static void plane(const scene_object *s, const double o[3], const double d[3], struct trace_hit *h)
{
	double len = sqrt(dot3(s->p[0], s->p[0])), n[3];
	for (int i = 0; i < 3 && len > 0; i++)
		n[i] = s->p[0][i] / len;
	double dn = len > 0 ? dot3(n, d) : 0;
	if (dn != 0)
		keep(h, (s->radius - dot3(n, o)) / dn, n);
}

/* Moeller-Trumbore; the normal is the flat one, or the corners' normals
 * (nrm, NULL for none) weighted by the barycentric coordinates, turned to face
 * the ray as POV-Ray turns a triangle's (a triangle has no inside). The sign of
 * n . d is the same in object and world space. */
static void triangle(const double *a, const double *b, const double *c, const double *const *nrm,
                     const double o[3], const double d[3], struct trace_hit *h)
{
	double e1[3], e2[3], p[3], q[3], s[3];
	for (int i = 0; i < 3; i++) {
		e1[i] = b[i] - a[i];
		e2[i] = c[i] - a[i];
		s[i] = o[i] - a[i];
	}
	cross3(d, e2, p);
	double det = dot3(e1, p);
	if (fabs(det) < 1e-300)
		return;
	double u = dot3(s, p) / det;
	cross3(s, e1, q);
	double v = dot3(d, q) / det, t = dot3(e2, q) / det;
	if (u < 0 || v < 0 || u + v > 1 || !(t > TRACE_EPSILON && t < h->t))
		return;
	double n[3];
	if (nrm && nrm[0])
		for (int i = 0; i < 3; i++)
			n[i] = (1 - u - v) * nrm[0][i] + u * nrm[1][i] + v * nrm[2][i];
	else
		cross3(e1, e2, n);
	if (dot3(n, d) > 0)
		for (int i = 0; i < 3; i++)
			n[i] = -n[i];
	keep(h, t, n);
}

static void mesh(const scene_mesh *m, const double o[3], const double d[3], struct trace_hit *h)
{
	for (int f = 0; f < m->n_faces; f++) {
		const int *vi = m->face[f];
		const double *nrm[3] = { NULL, NULL, NULL };
		if (m->n_nrm > 0)
			for (int k = 0; k < 3; k++)
				nrm[k] = m->nrm[m->face_nrm ? m->face_nrm[f][k] : vi[k]];
		triangle(m->v[vi[0]], m->v[vi[1]], m->v[vi[2]], nrm, o, d, h);
	}
}

static void shape(const scene *sc, const scene_object *s, const double o[3], const double d[3], struct trace_hit *h)
{
	const double *sn[3] = { s->n[0], s->n[1], s->n[2] };
	switch (s->shape) {
	case SHAPE_SPHERE: sphere(s, o, d, h); break;
	case SHAPE_BOX: box(s, o, d, h); break;
	case SHAPE_PLANE: plane(s, o, d, h); break;
	case SHAPE_TRIANGLE: triangle(s->p[0], s->p[1], s->p[2], NULL, o, d, h); break;
	case SHAPE_SMOOTH_TRIANGLE: triangle(s->p[0], s->p[1], s->p[2], sn, o, d, h); break;
	case SHAPE_MESH: mesh(&sc->meshes[s->mesh], o, d, h); break;
	}
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
		struct trace_hit h = { .t = best };
		shape(sc, s, lo, ld, &h);
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
