/* eval_spline.c: POV-Ray's splines, values that a scene calls like functions.
 *
 *   spline { [SPLINE_IDENTIFIER] [linear_spline | quadratic_spline | cubic_spline |
 *            natural_spline] Time, Value [,] Time, Value ... }
 *   Spline(Time [, SPLINE_TYPE])
 *
 * The interpolations are POV-Ray 3.7's (core/math/spline.cpp), so a scene moves
 * along the same path in both: linear between neighbours; quadratic through the
 * three points around the segment (the first segment uses its right-hand
 * three); cubic_spline is Catmull-Rom, whose first and last points only steer
 * (before the second point it gives the second, after the next-to-last that
 * one, and the mean of the two points of a spline of two); natural_spline is
 * the cubic with zero second derivative at both ends. Outside the times of the
 * points, the first or last point. Entries are kept sorted by time; a time given
 * twice keeps the later value. 'spline' and the type words are plain
 * identifiers, as 'file' is (src/ast.h, AST_WORD_): eclat's lexer reserves none
 * of them.
 *
 * A spline value is V_SPLINE with its entries in arr (time, then a 5-component
 * vector, for each point), its type in v[0] and the components of its values
 * (the largest of its points', at least 2, as in POV-Ray) in n. */
#include <math.h>
#include <string.h>

#include "eval_int.h"

enum { SPL_LINEAR, SPL_QUADRATIC, SPL_CUBIC, SPL_NATURAL };

static int spline_type(const char *name)
{
	static const char *const names[] = { AST_WORD_LINEAR_SPLINE, AST_WORD_QUADRATIC_SPLINE, AST_WORD_CUBIC_SPLINE,
		                             AST_WORD_NATURAL_SPLINE }; /* ORDER: SPL_ */
	for (int i = 0; i < 4; i++)
		if (strcmp(name, names[i]) == 0)
			return i;
	return -1;
}

/* Entry i's time and component k. */
#define T(a, i) ((a)->elems[2 * (i)].v[0])
#define V(a, i, k) ((a)->elems[2 * (i) + 1].v[k])

static void insert(struct array *a, double t, const double v[5])
{
	int n = a->n / 2, i = 0;
	while (i < n && T(a, i) < t)
		i++;
	if (i < n && T(a, i) == t) {
		memcpy(a->elems[2 * i + 1].v, v, 5 * sizeof *v);
		return;
	}
	a->elems = eval_xrealloc(a->elems, (size_t)(a->n + 2) * sizeof *a->elems);
	memmove(&a->elems[2 * i + 2], &a->elems[2 * i], (size_t)(a->n - 2 * i) * sizeof *a->elems);
	a->elems[2 * i] = eval_float(t);
	a->elems[2 * i + 1] = (value){ .kind = V_VECTOR, .n = 5 };
	memcpy(a->elems[2 * i + 1].v, v, 5 * sizeof *v);
	a->n += 2;
	a->size[0] = a->n;
}

/* "cubic_spline -2, <...>" parses as the difference cubic_spline - 2, the type
 * word being an identifier: the type of such a sum's leftmost term, or -1. */
static int leading_type(const ast_node *n)
{
	while (n->kind == AST_BINARY && (n->op == '+' || n->op == '-'))
		n = n->kids[0];
	return n->kind == AST_IDENT ? spline_type(n->str) : -1;
}

/* The time such a sum gives without its type word. */
static int time_after_type(struct eval *e, const ast_node *n, double *t)
{
	double r;
	if (n->kind == AST_IDENT) {
		*t = 0;
		return 0;
	}
	if (time_after_type(e, n->kids[0], t) || eval_expect_float(e, n->kids[1], &r))
		return -1;
	*t = n->op == '+' ? *t + r : *t - r;
	return 0;
}

/* The point at time t: the value is the next item, a float or a vector. */
static int entry(struct eval *e, struct cursor *c, double t, const ast_node *time, value *spl)
{
	int err = 0;
	const ast_node *item = eval_next_expr(c, &err);
	if (!item) {
		if (!err)
			eval_error(e, time->loc, "a spline's time needs a value after it");
		return -1;
	}
	value v;
	if (eval_expr(e, item, &v))
		return -1;
	if (!eval_is_numeric(v.kind)) {
		eval_error(e, item->loc, "a spline's value is a float or a vector, not %s", eval_kind_name(v.kind));
		eval_value_free(&v);
		return -1;
	}
	double w[5];
	int n = v.kind == V_FLOAT ? 1 : v.n;
	eval_widen(&v, 5, w);
	eval_value_free(&v);
	if (n > spl->n)
		spl->n = n;
	insert(spl->arr, t, w);
	return 0;
}

int eval_spline_value(struct eval *e, const ast_node *b, value *out)
{
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true;
	const ast_node *item;
	*out = (value){ .kind = V_SPLINE, .n = 2, .arr = eval_xrealloc(NULL, sizeof *out->arr) };
	*out->arr = (struct array){ .dims = 1 };
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		const value *old;
		double t;
		if (item->kind == AST_IDENT && spline_type(item->str) >= 0) {
			out->v[0] = spline_type(item->str);
		} else if (AST_IS_EXPRESSION(item->kind) && leading_type(item) >= 0) {
			out->v[0] = leading_type(item);
			rc = time_after_type(e, item, &t) || entry(e, &c, t, item, out) ? -1 : 0;
		} else if (first && item->kind == AST_IDENT && (old = eval_lookup(e, item->str)) && old->kind == V_SPLINE) {
			eval_value_free(out);
			*out = eval_value_copy(old);
		} else if (AST_IS_EXPRESSION(item->kind)) {
			rc = eval_expect_float(e, item, &t) || entry(e, &c, t, item, out) ? -1 : 0;
		} else {
			rc = eval_not_valid(e, item, "a spline");
		}
		first = false;
	}
	eval_cursor_free(&c);
	if (rc == 0 && !err && out->arr->n == 0) {
		eval_error(e, b->loc, "a spline needs at least one point: Time, Value");
		rc = -1;
	}
	if (rc || err) {
		eval_value_free(out);
		return -1;
	}
	return 0;
}

/* The index of the first point whose time is above t: 0 before the first,
 * n from the last one on. */
static int segment_end(const struct array *a, double t)
{
	int n = a->n / 2, i = 0;
	if (t <= T(a, 0))
		return 0;
	if (t >= T(a, n - 1))
		return n;
	while (i < n && T(a, i) < t)
		i++;
	return i;
}

static double linear(const struct array *a, int i, int k, double t)
{
	return V(a, i, k) + (t - T(a, i)) * (V(a, i + 1, k) - V(a, i, k)) / (T(a, i + 1) - T(a, i));
}

/* The parabola through points i - 1, i, i + 1 (Lagrange's form). */
static double quadratic(const struct array *a, int i, int k, double t)
{
	double t0 = T(a, i - 1), t1 = T(a, i), t2 = T(a, i + 1);
	return V(a, i - 1, k) * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)) +
	       V(a, i, k) * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)) +
	       V(a, i + 1, k) * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
}

/* Catmull-Rom on the segment from point i to i + 1, tangents the mean slopes. */
static double catmull_rom(const struct array *a, int i, int k, double t)
{
	double dt = T(a, i + 1) - T(a, i), u = (t - T(a, i)) / dt;
	double s0 = (V(a, i, k) - V(a, i - 1, k)) / (T(a, i) - T(a, i - 1));
	double s1 = (V(a, i + 1, k) - V(a, i, k)) / dt;
	double s2 = (V(a, i + 2, k) - V(a, i + 1, k)) / (T(a, i + 2) - T(a, i + 1));
	double m0 = (s0 + s1) / 2 * dt, m1 = (s1 + s2) / 2 * dt;
	double u2 = u * u, u3 = u2 * u;
	return V(a, i, k) * (2 * u3 - 3 * u2 + 1) + V(a, i + 1, k) * (3 * u2 - 2 * u3) + m0 * (u3 - 2 * u2 + u) +
	       m1 * (u3 - u2);
}

/* The natural cubic spline's second derivatives at the points (0 at both
 * ends), by the tridiagonal system's elimination. */
static void second_derivatives(const struct array *a, int k, double *m)
{
	int n = a->n / 2;
	double h[n], slope[n], diag[n], rhs[n];
	for (int i = 0; i < n; i++)
		diag[i] = 1, rhs[i] = 0;
	for (int i = 0; i + 1 < n; i++) {
		h[i] = T(a, i + 1) - T(a, i);
		slope[i] = (V(a, i + 1, k) - V(a, i, k)) / h[i];
	}
	for (int i = 1; i + 1 < n; i++) {
		diag[i] = 2 * (h[i - 1] + h[i]);
		rhs[i] = 6 * (slope[i] - slope[i - 1]);
		if (i > 1) {
			diag[i] -= h[i - 1] * h[i - 1] / diag[i - 1];
			rhs[i] -= h[i - 1] * rhs[i - 1] / diag[i - 1];
		}
	}
	m[0] = m[n - 1] = 0;
	for (int i = n - 2; i > 0; i--)
		m[i] = (rhs[i] - h[i] * m[i + 1]) / diag[i];
}

static double natural(const struct array *a, int i, int k, double t)
{
	double m[a->n / 2];
	second_derivatives(a, k, m);
	double h = T(a, i + 1) - T(a, i), x = t - T(a, i);
	double slope = (V(a, i + 1, k) - V(a, i, k)) / h - h / 6 * (m[i + 1] + 2 * m[i]);
	return V(a, i, k) + x * (slope + x * (m[i] / 2 + x * (m[i + 1] - m[i]) / (6 * h)));
}

static double component(const struct array *a, int type, double t, int k)
{
	int n = a->n / 2, i = segment_end(a, t);
	if (n == 1)
		return V(a, 0, k);
	if (type == SPL_CUBIC) {
		if (n == 2)
			return (V(a, 0, k) + V(a, 1, k)) / 2;
		if (i < 2)
			return V(a, 1, k);
		if (i >= n - 1)
			return V(a, n - 2, k);
		return catmull_rom(a, i - 1, k, t);
	}
	if (i == 0)
		return V(a, 0, k);
	if (i >= n)
		return V(a, n - 1, k);
	if (type == SPL_QUADRATIC && n > 2)
		return quadratic(a, i > 1 ? i - 1 : i, k, t);
	if (type == SPL_NATURAL)
		return natural(a, i - 1, k, t);
	return linear(a, i - 1, k, t);
}

/* Spline(Time [, SPLINE_TYPE]) */
int eval_spline_call(struct eval *e, const ast_node *call, const value *spl, value *out)
{
	double t;
	int type = (int)spl->v[0];
	if (call->n_kids < 1 || call->n_kids > 2) {
		eval_error(e, call->loc, "spline '%s' takes a time and, optionally, a spline type", call->str);
		return -1;
	}
	if (call->n_kids == 2 && (call->kids[1]->kind != AST_IDENT || (type = spline_type(call->kids[1]->str)) < 0)) {
		eval_error(e, call->kids[1]->loc, "expected linear_spline, quadratic_spline, cubic_spline or natural_spline");
		return -1;
	}
	if (eval_expect_float(e, call->kids[0], &t))
		return -1;
	*out = (value){ .kind = V_VECTOR, .n = spl->n };
	for (int k = 0; k < 5; k++)
		out->v[k] = k < spl->n ? component(spl->arr, type, t, k) : 0;
	return 0;
}
