/* eval_poly.c: the arguments of POV-Ray's polynomial surfaces (Parse_Poly and
 * Parse_Polynom in its parser), read into a scene_poly (src/shape_poly.c):
 *
 *   poly { Order, <c0, c1, ...> }       Order from 2 to 35, (Order+1)(Order+2)(Order+3)/6 numbers
 *   cubic { <c0, ..., c19> }
 *   quartic { <c0, ..., c34> }
 *   polynomial { Order, xyz(i, j, k): c, ... }   every other coefficient 0
 *
 * The grammar drops the colon after xyz(i, j, k), so a term is a call of xyz
 * and then its number. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"
#include "roots.h"

static int terms(int order)
{
	return (order + 1) * (order + 2) * (order + 3) / 6;
}

/* The index of x^i y^j z^k in POV-Ray's order: the terms of higher powers of
 * x come first, then those of higher powers of y, then of z. */
static int term_index(int order, int i, int j, int k)
{
	int a = order - i, b = order - i - j, c = order - i - j - k;
	return a * (a + 1) * (a + 2) / 6 + b * (b + 1) / 2 + c;
}

static const char *name_of(const ast_node *b)
{
	return b->kw == KW_UNKNOWN ? b->str : ast_keyword_name(b->kw);
}

/* Order, as poly and polynomial begin. */
static int read_order(struct eval *e, struct cursor *c, const ast_node *b, int *order)
{
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, b->loc, "%s needs an order from 2 to %d first", name_of(b), ROOTS_MAX_ORDER);
		return -1;
	}
	double f;
	if (eval_expect_float(e, arg, &f))
		return -1;
	if (!(f >= 2 && f < ROOTS_MAX_ORDER + 1)) {
		eval_error(e, arg->loc, "the order of a %s is %g: it must be from 2 to %d", name_of(b), f, ROOTS_MAX_ORDER);
		return -1;
	}
	*order = (int)f;
	return 0;
}

/* <c0, c1, ...>: exactly as many numbers as the order has terms. */
static int read_coefficients(struct eval *e, struct cursor *c, const ast_node *b, int order, double *out)
{
	int err = 0, n = terms(order);
	const ast_node *arg = eval_next_expr(c, &err);
	if (err)
		return -1;
	if (!arg || arg->kind != AST_VECTOR) {
		eval_error(e, arg ? arg->loc : b->loc, "a %s of order %d needs its %d coefficients as <c0, c1, ...>",
		           name_of(b), order, n);
		return -1;
	}
	if (arg->n_kids != n) {
		eval_error(e, arg->loc, "a %s of order %d has %d coefficients, not %d", name_of(b), order, n, arg->n_kids);
		return -1;
	}
	for (int i = 0; i < n; i++) {
		if (eval_expect_float(e, arg->kids[i], &out[i]))
			return -1;
		if (!isfinite(out[i])) {
			eval_error(e, arg->kids[i]->loc, "coefficient %d of the %s is not a number", i, name_of(b));
			return -1;
		}
	}
	return 0;
}

/* xyz(i, j, k): c terms, as many as there are. */
static int read_terms(struct eval *e, struct cursor *c, const ast_node *b, int order, double *out)
{
	int err = 0;
	const ast_node *item;
	while ((item = eval_next_expr(c, &err)) != NULL) {
		if (item->kind != AST_CALL || strcmp(item->str, AST_WORD_XYZ) != 0) {
			eval_error(e, item->loc, "expected a term xyz(i, j, k): Coefficient of the %s", name_of(b));
			return -1;
		}
		if (item->n_kids != 3) {
			eval_error(e, item->loc, "xyz takes three powers, not %d", item->n_kids);
			return -1;
		}
		double p[3], v;
		for (int k = 0; k < 3; k++)
			if (eval_expect_float(e, item->kids[k], &p[k]))
				return -1;
		if (!(p[0] >= 0 && p[1] >= 0 && p[2] >= 0 && p[0] + p[1] + p[2] < order + 1)) {
			eval_error(e, item->loc, "xyz(%g, %g, %g) is past the %s's order %d", p[0], p[1], p[2], name_of(b),
			           order);
			return -1;
		}
		const ast_node *val = eval_next_expr(c, &err);
		if (!val) {
			if (!err)
				eval_error(e, item->loc, "xyz(%g, %g, %g) needs ': Coefficient' after it", p[0], p[1], p[2]);
			return -1;
		}
		if (eval_expect_float(e, val, &v))
			return -1;
		if (!isfinite(v)) {
			eval_error(e, val->loc, "the coefficient of xyz(%g, %g, %g) is not a number", p[0], p[1], p[2]);
			return -1;
		}
		out[term_index(order, (int)p[0], (int)p[1], (int)p[2])] = v;
	}
	return err ? -1 : 0;
}

int eval_poly_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int order = o->shape == SHAPE_CUBIC ? 3 : 4;
	if ((o->shape == SHAPE_POLY || o->shape == SHAPE_POLYNOMIAL) && read_order(e, c, b, &order))
		return -1;
	scene_poly pl = { .order = order, .c = eval_xrealloc(NULL, (size_t)terms(order) * sizeof *pl.c) };
	memset(pl.c, 0, (size_t)terms(order) * sizeof *pl.c);
	int rc = o->shape == SHAPE_POLYNOMIAL ? read_terms(e, c, b, order, pl.c)
	                                      : read_coefficients(e, c, b, order, pl.c);
	if (rc) {
		free(pl.c);
		return -1;
	}
	o->param[0] = order;
	o->poly = scene_add_poly(e->s, &pl);
	return 0;
}

/* POV-Ray's bounded_by is not only a hint: a ray that misses the bound, from
 * outside it, misses the object, and a poly reaching past its bound is cut
 * there for such rays (objects/quartic/hyptorus.pov). A bound of one sphere
 * or box is kept with the poly, in a copy of its coefficients of its own;
 * other bounds are hints, as for every other shape. */
void eval_poly_bound(struct eval *e, scene_object *o, const struct objval *bound)
{
	if (o->shape != SHAPE_POLY && o->shape != SHAPE_CUBIC && o->shape != SHAPE_QUARTIC &&
	    o->shape != SHAPE_POLYNOMIAL)
		return;
	if (!bound || bound->n_objs != 1 || bound->n_csgs != 0)
		return;
	const scene_object *b = &bound->objs[0];
	double centre[3], size[3];
	int kind;
	if (b->shape == SHAPE_SPHERE) {
		kind = SCENE_BOUND_SPHERE;
		for (int k = 0; k < 3; k++) {
			centre[k] = b->p[0][k];
			size[k] = b->radius;
		}
	} else if (b->shape == SHAPE_BOX) {
		kind = SCENE_BOUND_BOX;
		for (int k = 0; k < 3; k++) {
			centre[k] = 0.5 * (b->p[0][k] + b->p[1][k]);
			size[k] = 0.5 * fabs(b->p[1][k] - b->p[0][k]);
		}
	} else {
		return;
	}
	if (!(size[0] > 0 && size[1] > 0 && size[2] > 0))
		return;
	const scene_poly *old = &e->s->polys[o->poly];
	size_t n = (size_t)terms(old->order);
	scene_poly pl = { .order = old->order, .c = eval_xrealloc(NULL, n * sizeof *pl.c), .bound = kind };
	memcpy(pl.c, old->c, n * sizeof *pl.c);
	xform sc = scene_xform_scale(size), tr = scene_xform_translate(centre), unit = scene_xform_then(&sc, &tr);
	pl.bound_xf = scene_xform_then(&unit, &b->xf);
	o->poly = scene_add_poly(e->s, &pl);
}
