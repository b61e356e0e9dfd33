/* eval_parametric.c: parametric { function { X(u, v) }, function { Y(u, v) },
 * function { Z(u, v) } <U1, V1>, <U2, V2> [accuracy A] [max_gradient G]
 * [precompute Depth, [x], [y], [z]] [contained_by { box | sphere }] }, POV-Ray
 * 3.7's parametric surface (Parse_Parametric), made into triangles here. POV-Ray
 * finds a ray's hit by subdividing the (u, v) rectangle against bounds from
 * max_gradient; eclat evaluates the functions on the host
 * (scene_function_eval) over a grid fine enough that a chord strays from the
 * surface by at most CHORD of the container's size, cuts the triangles to the
 * container (a box exactly, a sphere along chords of its surface), and gives
 * every corner POV-Ray's normal there (the cross of the steps of accuracy in u
 * and v) and POV-Ray's uv there, the (u, v) it was made at (what POV-Ray's
 * search leaves: the corner of its last, smallest square of parameters),
 * which a cut to the container blends as it blends the normal. The mesh goes
 * to scene.meshes and is placed as a height field's is
 * (src/shape_tessellated.c). max_gradient and precompute only speed POV-Ray's
 * search up: read and checked, they change nothing here. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

#define FIRST 64          /* the grid the curvature is measured on */
#define CHORD 5e-5        /* the most a triangle strays from the surface, of the container's diagonal */
#define TURN 0.03         /* the most the normal turns from a corner to the next, in radians */
#define MAX_CELLS (640 * 640)
#define BYTES_PER_CELL 264   /* two faces with their normals and uv, a vertex, a normal, a uv, and what clipping adds */

struct surface {
	const scene *s;
	int f[3];
	double accuracy;
	bool sphere;          /* the container: a sphere (c, r) or a box (lo, hi) */
	double lo[3], hi[3], c[3], r;
};

static void point(const struct surface *sf, double u, double v, double x[3])
{
	double args[3] = { u, v, 0 };
	for (int k = 0; k < 3; k++)
		x[k] = scene_function_eval(sf->s, sf->f[k], args);
}

/* POV-Ray's normal at (u, v): the cross of the steps of accuracy along u and v. */
static void normal(const struct surface *sf, double u, double v, const double x[3], double n[3])
{
	double a[3], b[3];
	point(sf, u + sf->accuracy, v, a);
	point(sf, u, v + sf->accuracy, b);
	for (int k = 0; k < 3; k++)
		a[k] -= x[k], b[k] -= x[k];
	n[0] = a[1] * b[2] - a[2] * b[1];
	n[1] = a[2] * b[0] - a[0] * b[2];
	n[2] = a[0] * b[1] - a[1] * b[0];
	double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	for (int k = 0; k < 3; k++)
		n[k] = l > 0 && isfinite(l) ? n[k] / l : 0;
}

/* ---- the mesh ---- */

struct build {
	scene_mesh m;
	int cap_v, cap_f;
};

/* A vertex at x with the normal n and POV-Ray's uv there (the surface's (u, v)). */
static int add_vertex(struct build *b, const double x[3], const double n[3], const double uv[2])
{
	if (b->m.n_v == b->cap_v) {
		b->cap_v = b->cap_v ? 2 * b->cap_v : 1024;
		b->m.v = eval_xrealloc(b->m.v, (size_t)b->cap_v * sizeof *b->m.v);
		b->m.nrm = eval_xrealloc(b->m.nrm, (size_t)b->cap_v * sizeof *b->m.nrm);
		b->m.uv = eval_xrealloc(b->m.uv, (size_t)b->cap_v * sizeof *b->m.uv);
	}
	memcpy(b->m.v[b->m.n_v], x, sizeof b->m.v[0]);
	memcpy(b->m.nrm[b->m.n_v], n, sizeof b->m.nrm[0]);
	memcpy(b->m.uv[b->m.n_v], uv, sizeof b->m.uv[0]);
	b->m.n_nrm = b->m.n_uv = b->m.n_v + 1;
	return b->m.n_v++;
}

static void add_face(struct build *b, int i, int j, int k)
{
	/* a sliver would be no triangle in floats: the lowering would warn of it */
	const double *p = b->m.v[i], *q = b->m.v[j], *r = b->m.v[k];
	double e1[3], e2[3], e3[3], c[3];
	for (int a = 0; a < 3; a++)
		e1[a] = q[a] - p[a], e2[a] = r[a] - p[a], e3[a] = r[a] - q[a];
	c[0] = e1[1] * e2[2] - e1[2] * e2[1];
	c[1] = e1[2] * e2[0] - e1[0] * e2[2];
	c[2] = e1[0] * e2[1] - e1[1] * e2[0];
	double l = fmax(fmax(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2], e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]),
	                e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2]);
	if (!(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) > 1e-6 * l))
		return;
	if (b->m.n_faces == b->cap_f) {
		b->cap_f = b->cap_f ? 2 * b->cap_f : 2048;
		b->m.face = eval_xrealloc(b->m.face, (size_t)b->cap_f * sizeof *b->m.face);
	}
	int t[3] = { i, j, k };
	memcpy(b->m.face[b->m.n_faces++], t, sizeof t);
}

/* ---- clipping to the container ---- */

/* How far outside the container's side k x is (k 0..5: a box's faces; the
 * sphere has one side): <= 0 inside. */
static double outside(const struct surface *sf, int k, const double x[3])
{
	if (sf->sphere) {
		double d2 = 0;
		for (int q = 0; q < 3; q++)
			d2 += (x[q] - sf->c[q]) * (x[q] - sf->c[q]);
		return d2 - sf->r * sf->r;
	}
	return k % 2 ? x[k / 2] - sf->hi[k / 2] : sf->lo[k / 2] - x[k / 2];
}

/* Where on the edge a to b (a inside side k, b outside) the side is crossed: s in [0, 1]. */
static double crossing(const struct surface *sf, int k, const double a[3], const double b[3])
{
	double fa = outside(sf, k, a), fb = outside(sf, k, b);
	if (!sf->sphere)
		return fa / (fa - fb);
	double d[3], w[3], A = 0, B = 0, C = 0;   /* |a + s d - c|^2 = r^2 */
	for (int q = 0; q < 3; q++) {
		d[q] = b[q] - a[q];
		w[q] = a[q] - sf->c[q];
		A += d[q] * d[q], B += w[q] * d[q], C += w[q] * w[q];
	}
	C -= sf->r * sf->r;
	double disc = B * B - A * C, s = A > 0 && disc >= 0 ? (-B + sqrt(disc)) / A : 0;
	return fmin(fmax(s, 0), 1);
}

#define MAX_POLY 12
struct corner {
	double x[3], n[3], uv[2];
};

/* Cuts the polygon p (n corners) to side k of the container: the corners left. */
static int clip_side(const struct surface *sf, int k, const struct corner *p, int n, struct corner *out)
{
	int m = 0;
	for (int i = 0; i < n; i++) {
		const struct corner *a = &p[i], *b = &p[(i + 1) % n];
		bool ina = outside(sf, k, a->x) <= 0, inb = outside(sf, k, b->x) <= 0;
		if (ina && m < MAX_POLY)
			out[m++] = *a;
		if (ina != inb && m < MAX_POLY) {
			double s = ina ? crossing(sf, k, a->x, b->x) : 1 - crossing(sf, k, b->x, a->x);
			struct corner c;
			for (int q = 0; q < 3; q++) {
				c.x[q] = a->x[q] + s * (b->x[q] - a->x[q]);
				c.n[q] = a->n[q] + s * (b->n[q] - a->n[q]);
			}
			for (int q = 0; q < 2; q++)
				c.uv[q] = a->uv[q] + s * (b->uv[q] - a->uv[q]);
			out[m++] = c;
		}
	}
	return m;
}

/* The triangle of vertices i, j, k, cut to the container. */
static void add_triangle(struct build *b, const struct surface *sf, int i, int j, int k)
{
	int idx[3] = { i, j, k }, sides = sf->sphere ? 1 : 6;
	bool all_in = true;
	for (int c = 0; c < 3; c++) {
		const double *x = b->m.v[idx[c]];
		if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
			return;
		for (int s = 0; s < sides; s++)
			all_in = all_in && outside(sf, s, x) <= 0;
	}
	if (all_in) {
		add_face(b, i, j, k);
		return;
	}
	struct corner p[MAX_POLY], q[MAX_POLY];
	int n = 3;
	for (int c = 0; c < 3; c++) {
		memcpy(p[c].x, b->m.v[idx[c]], sizeof p[c].x);
		memcpy(p[c].n, b->m.nrm[idx[c]], sizeof p[c].n);
		memcpy(p[c].uv, b->m.uv[idx[c]], sizeof p[c].uv);
	}
	for (int s = 0; s < sides && n >= 3; s++) {
		n = clip_side(sf, s, p, n, q);
		memcpy(p, q, (size_t)n * sizeof *p);
	}
	if (n < 3)
		return;
	int first = add_vertex(b, p[0].x, p[0].n, p[0].uv), prev = add_vertex(b, p[1].x, p[1].n, p[1].uv);
	for (int c = 2; c < n; c++) {
		int next = add_vertex(b, p[c].x, p[c].n, p[c].uv);
		add_face(b, first, prev, next);
		prev = next;
	}
}

/* ---- the grid ---- */

/* The angle between unit vectors a and b (0 when either is none). */
static double turn(const double a[3], const double b[3])
{
	double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
	return isfinite(c) && (a[0] || a[1] || a[2]) && (b[0] || b[1] || b[2]) ? acos(fmin(fmax(c, -1), 1)) : 0;
}

/* How many cells along u and v: enough that the second differences measured
 * on a FIRST x FIRST grid, scaled down by the square of the step, stay within
 * the chord's tolerance, and that the normal, which the triangles blend
 * between their corners, turns by at most TURN from a corner to the next (a
 * twisted strip is straight along v, but its normal turns). */
static void grid_size(const struct surface *sf, const double uv[2][2], double size, int *nu, int *nv)
{
	static double x[FIRST + 1][FIRST + 1][3], n[FIRST + 1][FIRST + 1][3];
	for (int i = 0; i <= FIRST; i++)
		for (int j = 0; j <= FIRST; j++) {
			double u = uv[0][0] + (uv[1][0] - uv[0][0]) * i / FIRST, v = uv[0][1] + (uv[1][1] - uv[0][1]) * j / FIRST;
			point(sf, u, v, x[i][j]);
			normal(sf, u, v, x[i][j], n[i][j]);
		}
	double du = 0, dv = 0, tu = 0, tv = 0;
	for (int i = 0; i < FIRST; i++)
		for (int j = 0; j < FIRST; j++) {
			tu = fmax(tu, turn(n[i][j], n[i + 1][j]));
			tv = fmax(tv, turn(n[i][j], n[i][j + 1]));
		}
	for (int i = 1; i < FIRST; i++)
		for (int j = 1; j < FIRST; j++) {
			double a = 0, b = 0;
			for (int q = 0; q < 3; q++) {
				double su = x[i - 1][j][q] - 2 * x[i][j][q] + x[i + 1][j][q];
				double sv = x[i][j - 1][q] - 2 * x[i][j][q] + x[i][j + 1][q];
				a += su * su, b += sv * sv;
			}
			if (isfinite(a) && isfinite(b))
				du = fmax(du, sqrt(a)), dv = fmax(dv, sqrt(b));
		}
	double tol = CHORD * size;
	double ku = ceil(FIRST * fmax(sqrt(du / (8 * tol)), tu / TURN));
	double kv = ceil(FIRST * fmax(sqrt(dv / (8 * tol)), tv / TURN));
	ku = fmin(fmax(ku, 8), 4096), kv = fmin(fmax(kv, 8), 4096);
	if (ku * kv > MAX_CELLS) {   /* as fine as the budget allows, in the same ratio */
		double f = sqrt(MAX_CELLS / (ku * kv));
		ku = fmax(floor(ku * f), 1), kv = fmax(floor(kv * f), 1);
	}
	*nu = (int)ku, *nv = (int)kv;
}

static int tessellate(struct eval *e, const struct surface *sf, const double uv[2][2], src_loc loc, int *mesh)
{
	double size = 0;
	for (int q = 0; q < 3; q++)
		size += sf->sphere ? 4 * sf->r * sf->r : (sf->hi[q] - sf->lo[q]) * (sf->hi[q] - sf->lo[q]);
	size = sqrt(size);
	int nu, nv;
	grid_size(sf, uv, size, &nu, &nv);
	if (eval_memory_claim(e, loc, (double)(nu + 1) * (nv + 1) * BYTES_PER_CELL, "a parametric's triangles"))
		return -1;
	struct build b = { .m = { .loc = loc } };
	for (int i = 0; i <= nu; i++)   /* vertex i (nv + 1) + j at u_i, v_j */
		for (int j = 0; j <= nv; j++) {
			double u = uv[0][0] + (uv[1][0] - uv[0][0]) * i / nu, v = uv[0][1] + (uv[1][1] - uv[0][1]) * j / nv;
			double x[3], n[3], at[2] = { u, v };
			point(sf, u, v, x);
			normal(sf, u, v, x, n);
			add_vertex(&b, x, n, at);
		}
	for (int i = 0; i < nu; i++)
		for (int j = 0; j < nv; j++) {
			int a = i * (nv + 1) + j, c = a + nv + 1;   /* (u0,v0) (u0,v1) (u1,v0) (u1,v1) */
			add_triangle(&b, sf, a, a + 1, c + 1);
			add_triangle(&b, sf, a, c + 1, c);
		}
	if (b.m.n_faces == 0) {
		eval_warning(e, loc, "a parametric with no point inside its container where its functions are numbers "
		             "draws nothing");
		free(b.m.v);
		free(b.m.nrm);
		free(b.m.uv);
		free(b.m.face);
		*mesh = -1;
		return 0;
	}
	/* each corner's normal and uv are its vertex's */
	b.m.face_nrm = eval_xrealloc(NULL, (size_t)b.m.n_faces * sizeof *b.m.face_nrm);
	memcpy(b.m.face_nrm, b.m.face, (size_t)b.m.n_faces * sizeof *b.m.face_nrm);
	b.m.face_uv = eval_xrealloc(NULL, (size_t)b.m.n_faces * sizeof *b.m.face_uv);
	memcpy(b.m.face_uv, b.m.face, (size_t)b.m.n_faces * sizeof *b.m.face_uv);
	*mesh = scene_add_mesh(e->s, &b.m);
	return 0;
}

/* ---- the items ---- */

static int function_item(struct eval *e, struct cursor *c, const ast_node *b, int i, int *f)
{
	int err = 0;
	const ast_node *item = eval_next(c, &err);
	const ast_node *def = NULL;
	if (item && item->kind == AST_FUNCTION) {
		def = item;
	} else if (item && item->kind == AST_IDENT) {
		const value *v = eval_lookup(e, item->str);
		if (v && v->kind == V_FUNCTION)
			def = v->node;
	}
	if (!def) {
		if (!err)
			eval_error(e, item ? item->loc : b->loc, "a parametric needs three functions { } of u and v first, "
			           "then <U1, V1>, <U2, V2>: this is not its function %d", i + 1);
		return -1;
	}
	int rc = eval_function_index(e, def, "the parametric is left out", f);
	return rc < 0 ? -1 : rc;
}

static int uv_item(struct eval *e, struct cursor *c, const ast_node *b, double out[2])
{
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err) {
			const ast_node *next = eval_next(c, &err);
			eval_error(e, next ? next->loc : b->loc, "a parametric needs <U1, V1>, <U2, V2> after its functions");
		}
		return -1;
	}
	value v;
	if (eval_expr(e, arg, &v))
		return -1;
	if (!eval_is_numeric(v.kind) || v.kind == V_COLOR) {
		eval_error(e, arg->loc, "a parametric's corner of (u, v): expected a 2-D vector, found %s",
		           eval_kind_name(v.kind));
		eval_value_free(&v);
		return -1;
	}
	double w[5];
	eval_widen(&v, 2, w);
	eval_value_free(&v);
	if (!isfinite(w[0]) || !isfinite(w[1])) {
		eval_error(e, arg->loc, "a parametric's corner of (u, v) is not a number");
		return -1;
	}
	out[0] = w[0], out[1] = w[1];
	return 0;
}

/* precompute Depth, [x], [y], [z] */
static int precompute(struct eval *e, struct cursor *c, const ast_node *item, const ast_node *neg)
{
	double depth;
	if (eval_word_float(e, c, item, neg, &depth))
		return -1;
	if (!(depth >= 1 && depth <= 20)) {
		eval_error(e, item->loc, "precompute's depth is 1 to 20, not %g (POV-Ray's \"invalid depth\")", depth);
		return -1;
	}
	int err = 0;
	const ast_node *w;
	while ((w = eval_next(c, &err)) != NULL) {
		if (w->kind != AST_IDENT || strlen(w->str) != 1 || !strchr("xyz", w->str[0])) {
			eval_unget(c, w);
			break;
		}
	}
	return err ? -1 : 0;
}

int eval_parametric_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	struct surface sf = { .s = e->s, .accuracy = 0.001, .lo = { -1, -1, -1 }, .hi = { 1, 1, 1 } };
	bool skip = false;
	for (int i = 0; i < 3; i++) {
		int rc = function_item(e, c, b, i, &sf.f[i]);
		if (rc < 0)
			return -1;
		skip = skip || rc > 0;
	}
	double uv[2][2];
	if (uv_item(e, c, b, uv[0]) || uv_item(e, c, b, uv[1]))
		return -1;
	for (int k = 0; k < 2; k++)   /* POV-Ray orders them */
		if (uv[0][k] > uv[1][k]) {
			double t = uv[0][k];
			uv[0][k] = uv[1][k];
			uv[1][k] = t;
		}
	int err = 0, rc = 0;
	double max_gradient = 1;
	scene_object box = { .p = { { -1, -1, -1 }, { 1, 1, 1 } } };
	const ast_node *item;
	while (rc == 0 && (item = eval_next(c, &err)) != NULL) {
		const ast_node *neg;
		const char *w = eval_word_item(item, &neg);
		if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_CONTAINED_BY) == 0)
			rc = eval_contained_by(e, item, &box);
		else if (w && strcmp(w, AST_WORD_ACCURACY) == 0)
			rc = eval_word_float(e, c, item, neg, &sf.accuracy);
		else if (w && strcmp(w, AST_WORD_MAX_GRADIENT) == 0)
			rc = eval_word_float(e, c, item, neg, &max_gradient);
		else if (w && strcmp(w, AST_WORD_PRECOMPUTE) == 0)
			rc = precompute(e, c, item, neg);
		else {
			eval_unget(c, item);   /* the object modifiers */
			break;
		}
	}
	if (rc || err)
		return -1;
	if (!(sf.accuracy > 0)) {
		eval_error(e, b->loc, "a parametric's accuracy must be above 0, not %g", sf.accuracy);
		return -1;
	}
	sf.sphere = box.n[0][0] != 0;
	memcpy(sf.lo, box.p[0], sizeof sf.lo);
	memcpy(sf.hi, box.p[1], sizeof sf.hi);
	memcpy(sf.c, box.p[0], sizeof sf.c);
	sf.r = fabs(box.radius);
	if (skip) {   /* --skip-unsupported: left out, with the warning */
		o->mesh = -1;
		return 0;
	}
	return tessellate(e, &sf, uv, b->loc, &o->mesh);
}
