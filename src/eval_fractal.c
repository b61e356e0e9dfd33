/* eval_fractal.c: the arguments and modifiers of POV-Ray 3.7's fractal
 * patterns (parser_materials.cpp's ParseMandelPattern, ParseJuliaPattern,
 * ParseMagnetPattern and the fractal modifiers of Parse_Pattern):
 *
 *   mandel ITERATIONS
 *   julia <Re, Im>, ITERATIONS
 *   magnet 1|2 mandel ITERATIONS
 *   magnet 1|2 julia <Re, Im>, ITERATIONS
 *   [exponent N] [interior TYPE, FACTOR] [exterior TYPE, FACTOR]
 *
 * into a scene_pigment's params (kernels/shared.h, dev_pattern). The pattern's
 * keyword has started the pattern; the first item after it is given here,
 * and the rest of the arguments are read from the cursor. */
#include <math.h>
#include <string.h>

#include "eval_int.h"

#define FRACTAL_MAX_EXPONENT 33   /* POV-Ray's kFractalMaxExponent */

bool eval_pattern_is_fractal(int kind)
{
	return kind == PATTERN_MANDEL || kind == PATTERN_JULIA || kind == PATTERN_MAGNET;
}

void eval_fractal_defaults(scene_pigment *pg)
{
	pg->params[0][0] = 0;   /* no iteration limit read yet */
	pg->params[0][1] = 2;
	pg->params[1][0] = 0;   /* interior 0, 1; exterior 1, 1 */
	pg->params[1][1] = 1;
	pg->params[1][2] = 1;
	pg->params[1][3] = 1;
}

static int next_float(struct eval *e, struct cursor *c, src_loc at, const char *what, double *out)
{
	int err = 0;
	const ast_node *n = eval_next_expr(c, &err);
	if (!n) {
		if (!err)
			eval_error(e, at, "expected %s", what);
		return -1;
	}
	return eval_expect_float(e, n, out);
}

/* The iteration limit: an integer of at least 1, as POV-Ray asks. */
static int iterations(struct eval *e, const ast_node *n, scene_pigment *pg)
{
	double v;
	if (eval_expect_float(e, n, &v))
		return -1;
	if (!(v >= 1)) {
		eval_error(e, n->loc, "the fractal iterations limit must be at least 1, found %g", v);
		return -1;
	}
	pg->params[0][0] = floor(fmin(v, 1e9));
	return 0;
}

static int next_iterations(struct eval *e, struct cursor *c, src_loc at, scene_pigment *pg)
{
	int err = 0;
	const ast_node *n = eval_next_expr(c, &err);
	if (!n) {
		if (!err)
			eval_error(e, at, "expected the fractal iterations limit");
		return -1;
	}
	return iterations(e, n, pg);
}

/* The julia constant: a 2-D vector (a float is both of its components). */
static int julia_constant(struct eval *e, const ast_node *n, scene_pigment *pg)
{
	double v[3];
	if (eval_expect_vector(e, n, v))
		return -1;
	pg->params[0][2] = v[0];
	pg->params[0][3] = v[1];
	return 0;
}

static int next_julia(struct eval *e, struct cursor *c, src_loc at, scene_pigment *pg)
{
	int err = 0;
	const ast_node *n = eval_next_expr(c, &err);
	if (!n) {
		if (!err)
			eval_error(e, at, "expected the julia constant, a 2-D vector");
		return -1;
	}
	return julia_constant(e, n, pg);
}

/* magnet TYPE mandel|julia ...: first is the type. */
static int magnet(struct eval *e, struct cursor *c, const ast_node *first, scene_pigment *pg)
{
	double type;
	if (eval_expect_float(e, first, &type))
		return -1;
	int err = 0;
	const ast_node *form = eval_next(c, &err);
	const char *name = form && form->kind == AST_IDENT && !eval_lookup(e, form->str) ? form->str : "";
	bool julia = strcmp(name, AST_WORD_JULIA) == 0;
	if (!form || (!julia && strcmp(name, AST_WORD_MANDEL) != 0)) {
		if (!err)
			eval_error(e, form ? form->loc : first->loc,
			           "invalid magnet pattern: expected 'mandel' or 'julia' after its type");
		return -1;
	}
	if (eval_int_of(type) != 1 && eval_int_of(type) != 2) {
		eval_error(e, first->loc, "invalid magnet-%s pattern type %g: valid types are 1 and 2", name, type);
		return -1;
	}
	pg->params[0][1] = (int)type + (julia ? 2 : 0);
	if (julia && next_julia(e, c, form->loc, pg))
		return -1;
	return next_iterations(e, c, form->loc, pg);
}

/* The arguments after the pattern's keyword, first being the first of them. */
static int arguments(struct eval *e, struct cursor *c, const ast_node *first, scene_pigment *pg)
{
	if (!AST_IS_EXPRESSION(first->kind)) {
		eval_error(e, first->loc, "expected the %s pattern's %s", scene_pattern_name(pg->kind),
		           pg->kind == PATTERN_MANDEL ? "iterations limit" : pg->kind == PATTERN_JULIA ?
		           "julia constant" : "type (1 or 2)");
		return -1;
	}
	if (pg->kind == PATTERN_MAGNET)
		return magnet(e, c, first, pg);
	if (pg->kind == PATTERN_JULIA)
		return julia_constant(e, first, pg) || next_iterations(e, c, first->loc, pg) ? -1 : 0;
	return iterations(e, first, pg);
}

/* exponent N: 2 to 33 for mandel and julia; POV-Ray warns and takes 2 for
 * the others. */
static int exponent(struct eval *e, const ast_node *item, scene_pigment *pg)
{
	double v;
	if (pg->kind == PATTERN_MAGNET) {
		eval_error(e, item->loc, "'exponent' is only valid in mandel or julia");
		return -1;
	}
	if (eval_expect_float(e, item->kids[0], &v))
		return -1;
	int n = eval_int_of(v);
	if (n < 2 || n > FRACTAL_MAX_EXPONENT) {
		eval_warning(e, item->loc, "invalid %s pattern exponent %g: supported exponents are 2 to %d; "
		             "using 2", scene_pattern_name(pg->kind), v, FRACTAL_MAX_EXPONENT);
		n = 2;
	}
	pg->params[0][1] = n;
	return 0;
}

/* interior TYPE, FACTOR (0-6) and exterior TYPE, FACTOR (0-8). */
static int colouring(struct eval *e, struct cursor *c, const ast_node *at, const ast_node *type_node,
                     bool interior, scene_pigment *pg)
{
	double type, factor;
	const char *which = interior ? "interior" : "exterior";
	int max = interior ? 6 : 8;
	if (type_node ? eval_expect_float(e, type_node, &type) : next_float(e, c, at->loc, "a type", &type))
		return -1;
	if (!(type >= 0 && type < max + 1)) {
		eval_error(e, at->loc, "invalid fractal pattern %s type %g: valid types are 0 to %d", which, type, max);
		return -1;
	}
	if (next_float(e, c, at->loc, "a factor after the type", &factor))
		return -1;
	pg->params[1][interior ? 0 : 2] = (int)type;
	pg->params[1][interior ? 1 : 3] = factor;
	return 0;
}

int eval_fractal_modifier(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg)
{
	if (pg->params[0][0] == 0)
		return arguments(e, c, item, pg);
	if (item->kind == AST_ARG && item->kw == KW_EXPONENT)
		return exponent(e, item, pg);
	if (item->kind == AST_ARG && item->kw == KW_INTERIOR)
		return colouring(e, c, item, item->kids[0], true, pg);
	if (item->kind == AST_IDENT && !eval_lookup(e, item->str) && strcmp(item->str, AST_WORD_EXTERIOR) == 0)
		return colouring(e, c, item, NULL, false, pg);
	return 1;
}

/* ---- julia_fractal { } ---- */

/* The word an item is, when it is an undeclared identifier. */
static const char *julia_word(struct eval *e, const ast_node *item)
{
	return item->kind == AST_IDENT && !eval_lookup(e, item->str) ? item->str : NULL;
}

/* A 4-D vector (a float is all four of its components). */
static int vector4(struct eval *e, const ast_node *n, double out[4])
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	int rc = 0;
	if (!eval_is_numeric(v.kind)) {
		eval_error(e, n->loc, "expected a 4-D vector, found %s", eval_kind_name(v.kind));
		rc = -1;
	} else {
		double w[5];
		eval_widen(&v, 4, w);
		memcpy(out, w, 4 * sizeof *out);
	}
	eval_value_free(&v);
	return rc;
}

/* slice <Slice4D>, Dist: made unit length, as POV-Ray does. */
static int slice(struct eval *e, struct cursor *c, const ast_node *at, scene_object *o)
{
	int err = 0;
	double s[4], dist;
	const ast_node *n = eval_next_expr(c, &err);
	if (!n) {
		if (!err)
			eval_error(e, at->loc, "expected the slice's 4-D vector");
		return -1;
	}
	if (vector4(e, n, s) || next_float(e, c, at->loc, "the slice's distance after its vector", &dist))
		return -1;
	double len2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[3] * s[3];
	if (fabs(len2) < 1e-10 || fabs(s[3]) < 1e-10) {   /* POV-Ray's EPSILON */
		eval_error(e, at->loc, fabs(len2) < 1e-10 ? "slice vector is zero" : "slice t component is zero");
		return -1;
	}
	double len = sqrt(len2);
	for (int k = 0; k < 3; k++)
		o->n[0][k] = s[k] / len;
	o->n[1][0] = s[3] / len;
	o->p[1][1] = dist;
	return 0;
}

/* julia_fractal { <Julia4D> [quaternion | hypercomplex] [sqr | cube]
 *                 [max_iteration N] [precision P] [slice <S4D>, Dist] ... },
 * POV-Ray's defaults: quaternion sqr, max_iteration 20, precision 20, slice
 * <0, 0, 0, 1>, 0. */
int eval_julia_fractal_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int err = 0;
	const ast_node *item = eval_next(c, &err);
	double j[4];
	if (!item || !AST_IS_EXPRESSION(item->kind) || julia_word(e, item)) {
		if (!err)
			eval_error(e, item ? item->loc : b->loc, "a julia_fractal needs its 4-D constant first");
		return -1;
	}
	if (vector4(e, item, j))
		return -1;
	memcpy(o->p[0], j, 3 * sizeof *j);
	o->p[1][0] = j[3];
	o->n[1][0] = 1;   /* slice <0, 0, 0, 1>, 0 */
	o->p[1][2] = 1.0 / 20;
	o->param[0] = 20;
	o->param[1] = JULIA_QUATERNION;
	o->param[2] = JULIA_SQR;
	while ((item = eval_next(c, &err)) != NULL) {
		const char *w = julia_word(e, item);
		double v;
		if (w && strcmp(w, AST_WORD_QUATERNION) == 0) {
			o->param[1] = JULIA_QUATERNION;
		} else if (w && strcmp(w, AST_WORD_HYPERCOMPLEX) == 0) {
			o->param[1] = JULIA_HYPERCOMPLEX;
		} else if (w && strcmp(w, AST_WORD_SQR) == 0) {
			o->param[2] = JULIA_SQR;
		} else if (w && strcmp(w, AST_WORD_CUBE) == 0) {
			o->param[2] = JULIA_CUBE;
		} else if (w && strcmp(w, AST_WORD_MAX_ITERATION) == 0) {
			if (next_float(e, c, item->loc, "a number after max_iteration", &v))
				return -1;
			o->param[0] = fmin(fmax(floor(v), 1), 1e6);   /* POV-Ray: at least 1 */
		} else if (w && strcmp(w, AST_WORD_PRECISION) == 0) {
			if (next_float(e, c, item->loc, "a number after precision", &v))
				return -1;
			o->p[1][2] = 1 / fmax(v, 1);
		} else if (w && strcmp(w, AST_WORD_SLICE) == 0) {
			if (slice(e, c, item, o))
				return -1;
		} else if (w && (strcmp(w, "reciprocal") == 0 || strcmp(w, "pwr") == 0 || strcmp(w, "ln") == 0)) {
			eval_error(e, item->loc, "julia_fractal's '%s' is not supported yet (sqr and cube are)", w);
			return -1;
		} else {
			eval_unget(c, item);   /* the object modifiers */
			break;
		}
	}
	return err ? -1 : 0;
}
