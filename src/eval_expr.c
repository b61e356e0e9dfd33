/* eval_expr.c: expressions: arithmetic, comparisons, colours, members, array
 * elements, calls of macros and functions, and POV-Ray's built-in functions. */
#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

#define EPSILON 1e-10      /* POV-Ray's, for = and the truth of a float */
#define MAX_EXPR_DEPTH 2000
#define MAX_STRING (1 << 24)

static int expr(struct eval *e, const ast_node *n, value *out);

/* ---- identifiers ---- */

/* The standard include file that declares name, if one does: a POV-Ray user's
 * "undeclared identifier 'White'" most often means a missing #include. Read
 * only on this error path. */
static const char *standard_include_of(struct eval *e, const ast_node *n)
{
	static const char *const files[] = { "colors.inc", "textures.inc", "metals.inc", "golds.inc", "glass.inc",
	                                     "finish.inc", "woods.inc", "stones.inc", "skies.inc", "shapes.inc" };
	size_t len = strlen(n->str);
	for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
		char *path = eval_find_file(e, n->loc.file, files[i]);
		size_t size;
		char *text = path && eval_access_allowed(e, path, false) ? diag_read_file(path, &size) : NULL;
		free(path);
		bool found = false;
		for (char *p = text; p && !found && (p = strstr(p, "#declare")) != NULL; p += 8) {
			char *q = p + 8;
			q += strspn(q, " \t");
			found = strncmp(q, n->str, len) == 0 && (q[len] == ' ' || q[len] == '\t' || q[len] == '=');
		}
		free(text);
		if (found)
			return files[i];
	}
	return NULL;
}

static void undeclared(struct eval *e, const ast_node *n, const char *what)
{
	char near[64];
	const char *inc = standard_include_of(e, n);
	eval_suggest(e, n->str, near, sizeof near);
	if (inc)
		eval_error(e, n->loc, "undeclared %s '%s'; %s declares it: #include \"%s\"", what, n->str, inc, inc);
	else if (near[0])
		eval_error(e, n->loc, "undeclared %s '%s'; did you mean '%s'?", what, n->str, near);
	else
		eval_error(e, n->loc, "undeclared %s '%s'", what, n->str);
}

static int identifier(struct eval *e, const ast_node *n, value *out)
{
	eval_used(e, n->str, n->loc);
	const value *v = eval_lookup(e, n->str);
	if (!v) {
		undeclared(e, n, "identifier");
		return -1;
	}
	if (v->kind == V_MACRO) {
		eval_error(e, n->loc, "macro '%s' is used without its arguments: write %s(...)", n->str, n->str);
		return -1;
	}
	*out = eval_value_copy(v);
	return 0;
}

/* An element of an array: the index of each dimension, 0-based. The indices are
 * evaluated first: one may call a macro that changes the array. */
static value *element(struct eval *e, const ast_node *n, int *err)
{
	const ast_node *base = n, *idx[8];
	int k = 0, at = 0, i[8];
	while (base->kind == AST_INDEX && k < 8) {
		idx[k++] = base->kids[1];
		base = base->kids[0];
	}
	for (int d = 0; d < k; d++)
		if (eval_expect_int(e, idx[k - 1 - d], &i[d])) {
			*err = 1;
			return NULL;
		}
	if (base->kind != AST_IDENT) {
		eval_error(e, n->loc, "only a declared array can be indexed");
		*err = 1;
		return NULL;
	}
	value *a = eval_reference(e, base, err);
	if (!a)
		return NULL;
	if (a->kind != V_ARRAY || k != a->arr->dims) {
		if (a->kind != V_ARRAY)
			eval_error(e, n->loc, "expected an array before '[', found %s", eval_kind_name(a->kind));
		else
			eval_error(e, n->loc, "the array has %d dimension%s, not %d", a->arr->dims,
			           a->arr->dims == 1 ? "" : "s", k);
		*err = 1;
		return NULL;
	}
	for (int d = 0; d < k; d++) {
		if (i[d] < 0 || i[d] >= a->arr->size[d]) {
			eval_error(e, idx[k - 1 - d]->loc, "index %d is out of the range 0 to %d", i[d], a->arr->size[d] - 1);
			*err = 1;
			return NULL;
		}
		at = at * a->arr->size[d] + i[d];
	}
	return &a->arr->elems[at];
}

value *eval_reference(struct eval *e, const ast_node *n, int *err)
{
	if (n->kind == AST_INDEX)
		return element(e, n, err);
	if (n->kind != AST_IDENT)
		return NULL;
	eval_used(e, n->str, n->loc);
	value *v = eval_lookup(e, n->str);
	if (!v) {
		undeclared(e, n, "identifier");
		*err = 1;
	}
	return v;
}

/* #ifdef (Name), #ifdef (A[1]), defined(Name): without complaining. */
bool eval_is_defined(struct eval *e, const ast_node *n)
{
	if (n->kind == AST_IDENT)
		return eval_lookup(e, n->str) != NULL;
	if (n->kind != AST_INDEX)
		return false;
	const ast_node *base = n;
	while (base->kind == AST_INDEX)
		base = base->kids[0];
	if (base->kind != AST_IDENT || !eval_lookup(e, base->str))
		return false;
	int err = 0;
	const value *v = element(e, n, &err);
	return v && v->kind != V_NONE;
}

/* ---- arithmetic ---- */

static bool numeric(struct eval *e, const ast_node *at, const value *v, const char *op)
{
	if (eval_is_numeric(v->kind))
		return true;
	eval_error(e, at->loc, "cannot apply '%s' to %s", op, eval_kind_name(v->kind));
	return false;
}

static double apply(int op, double a, double b)
{
	switch (op) {
	case '+': return a + b;
	case '-': return a - b;
	case '*': return a * b;
	case '/': return a / b;
	case '<': return a < b;
	case '>': return a > b;
	case '=': return !(fabs(a - b) > EPSILON);
	case OP_NE: return fabs(a - b) > EPSILON;
	case OP_LE: return a <= b || !(fabs(a - b) > EPSILON);
	case OP_GE: return a >= b || !(fabs(a - b) > EPSILON);
	case '&': return fabs(a) > EPSILON && fabs(b) > EPSILON;
	default: return fabs(a) > EPSILON || fabs(b) > EPSILON;
	}
}

/* "abc" < "abd": POV-Ray compares strings with the relational operators. */
static int string_compare(struct eval *e, const ast_node *n, value *a, value *b, value *out)
{
	int ok = a->kind == V_STRING && b->kind == V_STRING && n->op != '+' && n->op != '-' &&
	         n->op != '*' && n->op != '/' && n->op != '&' && n->op != '|';
	if (!ok)
		eval_error(e, n->loc, "cannot apply '%s' to %s and %s", ast_op_name(n->op), eval_kind_name(a->kind),
		           eval_kind_name(b->kind));
	else
		*out = eval_float(apply(n->op, strcmp(a->str, b->str), 0));
	eval_value_free(a);
	eval_value_free(b);
	return ok ? 0 : -1;
}

/* Component by component; a float meets a vector as that vector with the float
 * in every component, a shorter vector a longer one padded with 0 (POV-Ray's
 * Promote_Express). Anything with a colour gives a colour. */
static int binary(struct eval *e, const ast_node *n, value *out)
{
	value a, b;
	if (expr(e, n->kids[0], &a))
		return -1;
	if (expr(e, n->kids[1], &b)) {
		eval_value_free(&a);
		return -1;
	}
	if (!eval_is_numeric(a.kind) || !eval_is_numeric(b.kind))
		return string_compare(e, n, &a, &b, out);
	int size = a.n > b.n ? a.n : b.n;
	*out = (value){ .kind = a.kind == V_COLOR || b.kind == V_COLOR ? V_COLOR
	                       : size == 1 ? V_FLOAT : V_VECTOR, .n = size };
	double x[5], y[5];
	eval_widen(&a, size, x);
	eval_widen(&b, size, y);
	for (int i = 0; i < size; i++) {
		if (n->op == '/' && y[i] == 0) {
			eval_error(e, n->loc, "division by zero");
			return -1;
		}
		out->v[i] = apply(n->op, x[i], y[i]);
	}
	return 0;
}

static int unary(struct eval *e, const ast_node *n, value *out)
{
	if (expr(e, n->kids[0], out))
		return -1;
	char op[2] = { (char)n->op, 0 };
	if (!numeric(e, n, out, op)) {
		eval_value_free(out);
		return -1;
	}
	for (int i = 0; i < out->n; i++)
		out->v[i] = n->op == '-' ? -out->v[i] : n->op == '!' ? !eval_truth(out->v[i]) : out->v[i];
	return 0;
}

/* (Cond ? A : B): only the branch taken is evaluated. */
static int conditional(struct eval *e, const ast_node *n, value *out)
{
	double c;
	if (eval_expect_float(e, n->kids[0], &c))
		return -1;
	return expr(e, n->kids[eval_truth(c) ? 1 : 2], out);
}

/* <A, B [, C [, D [, E]]]>: the components are floats. */
static int vector(struct eval *e, const ast_node *n, value *out)
{
	if (n->n_kids < 2 || n->n_kids > 5) {
		eval_error(e, n->loc, "a vector has 2 to 5 components, this one has %d", n->n_kids);
		return -1;
	}
	*out = (value){ .kind = V_VECTOR, .n = n->n_kids };
	for (int i = 0; i < n->n_kids; i++)
		if (eval_expect_float(e, n->kids[i], &out->v[i]))
			return -1;
	return 0;
}

/* V.x V.y V.z V.t, C.red C.green C.blue C.filter C.transmit C.gray, U.u U.v */
static int member(struct eval *e, const ast_node *n, value *out)
{
	static const char *const names[][3] = {
		{ "x", "u", "red" }, { "y", "v", "green" }, { "z", "blue", "" }, { "t", "filter", "" },
		{ "transmit", "", "" },
	};
	value v;
	if (expr(e, n->kids[0], &v))
		return -1;
	if (!numeric(e, n, &v, ".")) {
		eval_value_free(&v);
		return -1;
	}
	if (strcmp(n->str, "gray") == 0) {
		double c[5];
		eval_widen(&v, 5, c);
		*out = eval_float(0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]);  /* POV-Ray 3.7's weights */
		return 0;
	}
	for (int i = 0; i < 5; i++)
		for (int k = 0; k < 3; k++)
			if (strcmp(names[i][k], n->str) == 0) {
				if (i >= v.n) {
					eval_error(e, n->loc, "'.%s' of %s of %d component%s", n->str, eval_kind_name(v.kind), v.n,
					           v.n == 1 ? "" : "s");
					return -1;
				}
				*out = eval_float(v.v[i]);
				return 0;
			}
	eval_error(e, n->loc, "expected x, y, z, t, u, v, red, green, blue, filter, transmit or gray after '.', found '%s'",
	           n->str);
	return -1;
}

/* ---- colours ---- */

double eval_srgb_decode(double c)
{
	return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static const int color_slots[][5] = {   /* which colour component each number fills */
	[KW_RGB] = { 0, 1, 2, -1, -1 }, [KW_RGBF] = { 0, 1, 2, 3, -1 },
	[KW_RGBT] = { 0, 1, 2, 4, -1 }, [KW_RGBFT] = { 0, 1, 2, 3, 4 },
	[KW_SRGB] = { 0, 1, 2, -1, -1 }, [KW_SRGBF] = { 0, 1, 2, 3, -1 },
	[KW_SRGBT] = { 0, 1, 2, 4, -1 }, [KW_SRGBFT] = { 0, 1, 2, 3, 4 },
};

static int slots_wanted(int kw)
{
	return kw == KW_RGB || kw == KW_SRGB ? 3 : kw == KW_RGBFT || kw == KW_SRGBFT ? 5 : 4;
}

/* srgb: sRGB to linear, then to the working gamma (assumed_gamma), as POV-Ray. */
static void srgb_to_linear(struct eval *e, double c[5])
{
	double g = e->s->assumed_gamma > 0 ? e->s->assumed_gamma : 1;
	for (int i = 0; i < 3; i++)
		c[i] = pow(eval_srgb_decode(c[i]), 1 / g);
}

/* rgb, rgbf, rgbt, rgbft (and srgb...) take 3, 4, 4 and 5 numbers: a float fills
 * them, a vector must have that many; from a colour they keep what they name. */
static int rgb_form(struct eval *e, const ast_node *n, const value *a, value *out)
{
	const int *slot = color_slots[n->kw];
	int want = slots_wanted(n->kw);
	*out = (value){ .kind = V_COLOR, .n = 5 };
	if (a->kind == V_COLOR) {
		for (int i = 0; i < want; i++)
			out->v[slot[i]] = a->v[slot[i]];
	} else if (a->kind != V_FLOAT && a->n != want) {
		eval_error(e, n->kids[0]->loc, "'%s' takes a vector of %d components, found %d",
		           ast_keyword_name(n->kw), want, a->n);
		return -1;
	} else {
		double w[5];
		eval_widen(a, want, w);
		for (int i = 0; i < want; i++)
			out->v[slot[i]] = w[i];
	}
	if (n->kw >= KW_SRGB && n->kw <= KW_SRGBT)
		srgb_to_linear(e, out->v);
	return 0;
}

/* red F, Base green F...: one component set in a colour (black by default). */
static int component_form(struct eval *e, const ast_node *n, value *out)
{
	value base = { .kind = V_COLOR, .n = 5 };
	if (n->n_kids == 2 && expr(e, n->kids[0], &base))
		return -1;
	return eval_component(e, n, &base, out);
}

int eval_component(struct eval *e, const ast_node *n, value *base_in, value *out)
{
	value base = *base_in, c;
	if (!numeric(e, n, &base, ast_keyword_name(n->kw))) {
		eval_value_free(&base);
		return -1;
	}
	double f;
	if (eval_expect_float(e, n->kids[n->n_kids - 1], &f))
		return -1;
	c = (value){ .kind = V_COLOR, .n = 5 };
	eval_widen(&base, 5, c.v);
	switch (n->kw) {
	case KW_RED: c.v[0] = f; break;
	case KW_GREEN: c.v[1] = f; break;
	case KW_BLUE: c.v[2] = f; break;
	case KW_FILTER: c.v[3] = f; break;
	case KW_TRANSMIT: c.v[4] = f; break;
	default: c.v[0] = c.v[1] = c.v[2] = f; break;   /* gray, an eclat extension */
	}
	*out = c;
	return 0;
}

/* color X marks X as a colour: a float fills all five components (filter and
 * transmit too, as in POV-Ray), a vector fills them in order. */
static int color(struct eval *e, const ast_node *n, value *out)
{
	enum kw_class cls = ast_keyword_class(n->kw);
	if (cls == KWC_COMP)
		return component_form(e, n, out);
	value a;
	if (expr(e, n->kids[0], &a))
		return -1;
	if (!eval_is_numeric(a.kind)) {
		eval_error(e, n->kids[0]->loc, "expected a colour after '%s', found %s", ast_keyword_name(n->kw),
		           eval_kind_name(a.kind));
		eval_value_free(&a);
		return -1;
	}
	if (cls == KWC_RGB)
		return rgb_form(e, n, &a, out);
	*out = (value){ .kind = V_COLOR, .n = 5 };
	eval_widen(&a, 5, out->v);
	return 0;
}

/* ---- built-in functions ---- */

static int nargs(struct eval *e, const ast_node *n, int lo, int hi)
{
	if (n->n_kids >= lo && n->n_kids <= hi)
		return 0;
	if (lo == hi)
		eval_error(e, n->loc, "%s() takes %d argument%s, not %d", ast_keyword_name(n->kw), lo, lo == 1 ? "" : "s",
		           n->n_kids);
	else
		eval_error(e, n->loc, "%s() takes %d to %d arguments, not %d", ast_keyword_name(n->kw), lo, hi, n->n_kids);
	return -1;
}

static int floats(struct eval *e, const ast_node *n, double *a, int count)
{
	for (int i = 0; i < count; i++)
		if (eval_expect_float(e, n->kids[i], &a[i]))
			return -1;
	return 0;
}

static int domain_error(struct eval *e, const ast_node *n, double x)
{
	eval_error(e, n->loc, "%s(%g) is not defined (a domain error)", ast_keyword_name(n->kw), x);
	return -1;
}

/* acos and asin clamp their argument with a warning, as POV-Ray does. */
static double clamp_unit(struct eval *e, const ast_node *n, double x)
{
	if (x >= -1 && x <= 1)
		return x;
	eval_warning(e, n->loc, "%s(%g): the argument is outside -1 to 1; using %g", ast_keyword_name(n->kw), x,
	             x > 1 ? 1.0 : -1.0);
	return x > 1 ? 1 : -1;
}

/* Functions of one float. */
static int math1(struct eval *e, const ast_node *n, double x, double *r)
{
	switch (n->kw) {
	case KW_ABS: *r = fabs(x); return 0;
	case KW_ACOS: *r = acos(clamp_unit(e, n, x)); return 0;
	case KW_ASIN: *r = asin(clamp_unit(e, n, x)); return 0;
	case KW_ACOSH: if (x < 1) return domain_error(e, n, x); *r = acosh(x); return 0;
	case KW_ASINH: *r = asinh(x); return 0;
	case KW_ATAN: *r = atan(x); return 0;
	case KW_ATANH: if (x <= -1 || x >= 1) return domain_error(e, n, x); *r = atanh(x); return 0;
	case KW_CEIL: *r = ceil(x); return 0;
	case KW_COS: *r = cos(x); return 0;
	case KW_COSH: *r = cosh(x); return 0;
	case KW_DEGREES: *r = x * 180 / M_PI; return 0;
	case KW_EXP: *r = exp(x); return 0;
	case KW_FLOOR: *r = floor(x); return 0;
	case KW_INT: *r = trunc(x); return 0;
	case KW_LN: if (x <= 0) return domain_error(e, n, x); *r = log(x); return 0;
	case KW_LOG: if (x <= 0) return domain_error(e, n, x); *r = log10(x); return 0;
	case KW_RADIANS: *r = x * M_PI / 180; return 0;
	case KW_SIN: *r = sin(x); return 0;
	case KW_SINH: *r = sinh(x); return 0;
	case KW_SQRT: if (x < 0) return domain_error(e, n, x); *r = sqrt(x); return 0;
	case KW_TAN: *r = tan(x); return 0;
	case KW_TANH: *r = tanh(x); return 0;
	default: return 1;
	}
}

/* Functions of two floats. */
static int math2(struct eval *e, const ast_node *n, double a, double b, double *r)
{
	switch (n->kw) {
	case KW_ATAN2:
		if (!eval_truth(a) && !eval_truth(b)) {
			eval_error(e, n->loc, "atan2(0, 0) is not defined (a domain error)");
			return -1;
		}
		*r = atan2(a, b);
		return 0;
	case KW_DIV:
	case KW_MOD:
		if (b == 0) {
			eval_error(e, n->loc, "division by zero in %s()", ast_keyword_name(n->kw));
			return -1;
		}
		*r = n->kw == KW_DIV ? trunc(a / b) : fmod(a, b);
		return 0;
	case KW_POW:
		if (a == 0 && b == 0) {
			eval_error(e, n->loc, "pow(0, 0) is not defined (a domain error)");
			return -1;
		}
		*r = pow(a, b);
		if (isnan(*r)) {
			eval_error(e, n->loc, "pow(%g, %g) is not defined (a domain error)", a, b);
			return -1;
		}
		return 0;
	default:
		return 1;
	}
}

/* POV-Ray's seed() and bitwise functions cast so, and its random sequences depend on it. */
int eval_int_of(double f)
{
	if (!(f > (double)INT_MIN - 1 && f < (double)INT_MAX + 1))
		return INT_MIN;
	return (int)f;
}

/* max(A, B...), min(...), bitwise_and(A, B...)... */
static int variadic(struct eval *e, const ast_node *n, double *r)
{
	if (n->n_kids < 1)
		return nargs(e, n, 1, 64);
	double a[64];
	int k = n->n_kids < 64 ? n->n_kids : 64;
	if (floats(e, n, a, k))
		return -1;
	*r = a[0];
	int bits = eval_int_of(a[0]);
	for (int i = 1; i < k; i++) {
		if (n->kw == KW_MAX && a[i] > *r)
			*r = a[i];
		if (n->kw == KW_MIN && a[i] < *r)
			*r = a[i];
		bits = n->kw == KW_BITWISE_AND ? bits & eval_int_of(a[i]) : n->kw == KW_BITWISE_OR ? bits | eval_int_of(a[i])
		     : bits ^ eval_int_of(a[i]);
	}
	if (n->kw != KW_MAX && n->kw != KW_MIN)
		*r = bits;
	return 0;
}

/* select(A, Neg, Zero [, Pos]): with three arguments, Zero for A >= 0. */
static int select3(struct eval *e, const ast_node *n, double *r)
{
	double a[4];
	if (nargs(e, n, 3, 4) || floats(e, n, a, n->n_kids))
		return -1;
	*r = a[0] < 0 ? a[1] : (n->n_kids == 3 || a[0] == 0) ? a[2] : a[3];
	return 0;
}

/* seed(F) makes a random stream, rand(S) draws from it: POV-Ray 3.7's generator,
 * state = state * 1812433253 + 12345 (mod 2^32), value = state / (2^32 - 1). */
static int rng(struct eval *e, const ast_node *n, double *r)
{
	double a;
	if (nargs(e, n, 1, 1) || floats(e, n, &a, 1))
		return -1;
	struct rng *g = &e->rng;
	if (n->kw == KW_SEED) {
		g->state = eval_xrealloc(g->state, (g->n + 1) * sizeof *g->state);
		g->state[g->n] = (unsigned)eval_int_of(a);
		*r = g->n++;
		return 0;
	}
	int i = eval_int_of(a);
	if (i < 0 || i >= g->n) {
		eval_error(e, n->kids[0]->loc, "rand() needs a stream made by seed(), not %g", a);
		return -1;
	}
	g->state[i] = g->state[i] * 1812433253u + 12345u;
	*r = (double)g->state[i] / 4294967295.0;
	return 0;
}

static int string_arg(struct eval *e, const ast_node *n, int i, char **s)
{
	return eval_expect_string(e, n->kids[i], s);
}

/* strlen asc val strcmp file_exists: floats of strings. */
static int string_float(struct eval *e, const ast_node *n, double *r)
{
	char *a, *b = NULL;
	int two = n->kw == KW_STRCMP;
	if (nargs(e, n, 1 + two, 1 + two) || string_arg(e, n, 0, &a))
		return -1;
	if (two && string_arg(e, n, 1, &b)) {
		free(a);
		return -1;
	}
	switch (n->kw) {
	case KW_STRLEN: *r = (double)strlen(a); break;
	case KW_ASC: *r = (unsigned char)a[0]; break;
	case KW_VAL: *r = atof(a); break;
	case KW_FILE_EXISTS: *r = eval_file_exists(e, n->loc.file, a); break;
	default: {
		const unsigned char *p = (const unsigned char *)a, *q = (const unsigned char *)b;
		while (*p && *p == *q)
			p++, q++;
		*r = (double)*p - (double)*q;   /* POV-Ray gives the difference, not just its sign */
	}
	}
	free(a);
	free(b);
	return 0;
}

/* dimensions(A), dimension_size(A, N) */
static int array_float(struct eval *e, const ast_node *n, double *r)
{
	if (nargs(e, n, n->kw == KW_DIMENSIONS ? 1 : 2, n->kw == KW_DIMENSIONS ? 1 : 2))
		return -1;
	int err = 0, d = 0;
	if (n->kw == KW_DIMENSION_SIZE && eval_expect_int(e, n->kids[1], &d))
		return -1;   /* first: it may run a macro that changes the array */
	const value *a = eval_reference(e, n->kids[0], &err);
	if (!a || a->kind != V_ARRAY) {
		if (!err)
			eval_error(e, n->kids[0]->loc, "%s() needs an array", ast_keyword_name(n->kw));
		return -1;
	}
	if (n->kw == KW_DIMENSIONS) {
		*r = a->arr->dims;
		return 0;
	}
	if (d < 1 || d > a->arr->dims) {
		eval_warning(e, n->kids[1]->loc, "dimension %d of an array of %d dimension%s; its size is 0", d,
		             a->arr->dims, a->arr->dims == 1 ? "" : "s");
		*r = 0;
		return 0;
	}
	*r = a->arr->size[d - 1];
	return 0;
}

static int float_function(struct eval *e, const ast_node *n, double *r)
{
	double a[2];
	switch (n->kw) {
	case KW_MAX: case KW_MIN: case KW_BITWISE_AND: case KW_BITWISE_OR: case KW_BITWISE_XOR:
		return variadic(e, n, r);
	case KW_SELECT: return select3(e, n, r);
	case KW_SEED: case KW_RAND: return rng(e, n, r);
	case KW_STRLEN: case KW_ASC: case KW_VAL: case KW_STRCMP: case KW_FILE_EXISTS:
		return string_float(e, n, r);
	case KW_DIMENSIONS: case KW_DIMENSION_SIZE: return array_float(e, n, r);
	case KW_DEFINED:
		if (nargs(e, n, 1, 1))
			return -1;
		*r = eval_is_defined(e, n->kids[0]);
		return 0;
	case KW_ATAN2: case KW_DIV: case KW_MOD: case KW_POW:
		if (nargs(e, n, 2, 2) || floats(e, n, a, 2))
			return -1;
		return math2(e, n, a[0], a[1], r);
	default:
		if (nargs(e, n, 1, 1) || floats(e, n, a, 1))
			return -1;
		return math1(e, n, a[0], r);
	}
}

/* str(F, Width, Precision) as POV-Ray writes it: printf's %f with the width
 * (a negative one pads with zeros) and the precision (a negative one is %f's 6). */
static void format_float(char *out, size_t size, double v, int width, int prec)
{
	char fmt[32], *p = fmt;
	*p++ = '%';
	if (width > 0)
		p += sprintf(p, "%d", width);
	else if (width < 0)
		p += sprintf(p, "0%d", width == INT_MIN ? 0 : -width);
	if (prec >= 0)
		p += sprintf(p, ".%d", prec > 100 ? 100 : prec);
	strcpy(p, "f");
	int k = snprintf(out, size, fmt, v);
	if (k < 0 || (size_t)k >= size) {
		strcpy(p, "g");
		snprintf(out, size, fmt, v);
	}
}

static int width_prec(struct eval *e, const ast_node *n, int at, int *w, int *p)
{
	double a[2];
	if (eval_expect_float(e, n->kids[at], &a[0]) || eval_expect_float(e, n->kids[at + 1], &a[1]))
		return -1;
	*w = eval_int_of(a[0]);
	*p = eval_int_of(a[1]);
	if (*w > 200 || *w < -200)
		*w = *w > 0 ? 200 : -200;
	return 0;
}

static int str_fn(struct eval *e, const ast_node *n, char **out)
{
	double v;
	int w, p;
	if (nargs(e, n, 3, 3) || eval_expect_float(e, n->kids[0], &v) || width_prec(e, n, 1, &w, &p))
		return -1;
	char buf[512];
	format_float(buf, sizeof buf, v, w, p);
	*out = eval_xstrdup(buf);
	return 0;
}

/* vstr(N, V, Separator, Width, Precision) */
static int vstr_fn(struct eval *e, const ast_node *n, char **out)
{
	int count, w, p;
	value v;
	char *sep;
	if (nargs(e, n, 5, 5) || eval_expect_int(e, n->kids[0], &count))
		return -1;
	if (count < 2 || count > 5) {
		eval_error(e, n->kids[0]->loc, "vstr() writes 2 to 5 components, not %d", count);
		return -1;
	}
	if (expr(e, n->kids[1], &v))
		return -1;
	if (!numeric(e, n->kids[1], &v, "vstr")) {
		eval_value_free(&v);
		return -1;
	}
	if (eval_expect_string(e, n->kids[2], &sep))
		return -1;
	if (width_prec(e, n, 3, &w, &p)) {
		free(sep);
		return -1;
	}
	double c[5];
	eval_widen(&v, count, c);
	size_t cap = 5 * 520 + 5 * strlen(sep) + 1, len = 0;
	char *s = eval_xrealloc(NULL, cap);
	for (int i = 0; i < count; i++) {
		format_float(s + len, 512, c[i], w, p);
		len += strlen(s + len);
		if (i + 1 < count)
			len += (size_t)sprintf(s + len, "%s", sep);
	}
	free(sep);
	*out = s;
	return 0;
}

static int concat_fn(struct eval *e, const ast_node *n, char **out)
{
	size_t len = 0;
	char *s = eval_xstrdup("");
	for (int i = 0; i < n->n_kids; i++) {
		char *a;
		if (eval_expect_string(e, n->kids[i], &a)) {
			free(s);
			return -1;
		}
		size_t k = strlen(a);
		if (len + k > MAX_STRING) {   /* a doubling loop would eat the memory first */
			eval_error(e, n->loc, "concat() would make a string of more than %d characters", MAX_STRING);
			free(a);
			free(s);
			return -1;
		}
		s = eval_xrealloc(s, len + k + 1);
		memcpy(s + len, a, k + 1);
		len += k;
		free(a);
	}
	*out = s;
	return 0;
}

/* substr(S, Position, Length): Position counts from 1. */
static int substr_fn(struct eval *e, const ast_node *n, char **out)
{
	char *s;
	int pos, len;
	if (nargs(e, n, 3, 3) || eval_expect_string(e, n->kids[0], &s))
		return -1;
	if (eval_expect_int(e, n->kids[1], &pos) || eval_expect_int(e, n->kids[2], &len)) {
		free(s);
		return -1;
	}
	if (pos < 1 || len < 0 || (size_t)pos - 1 + (size_t)len > strlen(s)) {
		eval_error(e, n->loc, "substr(\"%s\", %d, %d) is outside the string", s, pos, len);
		free(s);
		return -1;
	}
	memmove(s, s + pos - 1, (size_t)len);
	s[len] = '\0';
	*out = s;
	return 0;
}

static int string_function(struct eval *e, const ast_node *n, char **out)
{
	double c;
	switch (n->kw) {
	case KW_STR: return str_fn(e, n, out);
	case KW_VSTR: return vstr_fn(e, n, out);
	case KW_CONCAT: return concat_fn(e, n, out);
	case KW_SUBSTR: return substr_fn(e, n, out);
	case KW_CHR:
		if (nargs(e, n, 1, 1) || eval_expect_float(e, n->kids[0], &c))
			return -1;
		if (c < 1 || c > 255) {
			eval_error(e, n->kids[0]->loc, "chr(%g): eclat's strings hold the characters 1 to 255", c);
			return -1;
		}
		*out = eval_xrealloc(NULL, 2);
		(*out)[0] = (char)(int)c;
		(*out)[1] = '\0';
		return 0;
	default:   /* strupr, strlwr */
		if (nargs(e, n, 1, 1) || eval_expect_string(e, n->kids[0], out))
			return -1;
		for (char *p = *out; *p; p++)
			*p = (char)(n->kw == KW_STRUPR ? toupper((unsigned char)*p) : tolower((unsigned char)*p));
		return 0;
	}
}

static int vectors(struct eval *e, const ast_node *n, double v[][3], int count)
{
	for (int i = 0; i < count; i++)
		if (eval_expect_vector(e, n->kids[i], v[i]))
			return -1;
	return 0;
}

/* vaxis_rotate(V, Axis, Degrees): POV-Ray's Compute_Axis_Rotation_Transform. */
static void axis_rotate(const double p[3], const double axis[3], double deg, double out[3])
{
	double l = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
	double a[3] = { axis[0] / l, axis[1] / l, axis[2] / l };
	double c = cos(deg * M_PI / 180), s = sin(deg * M_PI / 180), m[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			m[i][j] = a[i] * a[j] * (1 - c) + (i == j ? c : 0);
	m[0][1] += a[2] * s; m[0][2] -= a[1] * s;
	m[1][0] -= a[2] * s; m[1][2] += a[0] * s;
	m[2][0] += a[1] * s; m[2][1] -= a[0] * s;
	for (int j = 0; j < 3; j++)
		out[j] = p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j];
}

static int vector_function(struct eval *e, const ast_node *n, value *out)
{
	double v[3][3], r[3], f;
	int two = n->kw == KW_VCROSS || n->kw == KW_VDOT || n->kw == KW_VROTATE;
	int count = n->kw == KW_VAXIS_ROTATE ? 3 : two ? 2 : 1;
	if (nargs(e, n, count, count) || vectors(e, n, v, count == 3 ? 2 : count))
		return -1;
	switch (n->kw) {
	case KW_VLENGTH:
	case KW_VDOT:
		f = n->kw == KW_VDOT ? v[0][0] * v[1][0] + v[0][1] * v[1][1] + v[0][2] * v[1][2]
		  : sqrt(v[0][0] * v[0][0] + v[0][1] * v[0][1] + v[0][2] * v[0][2]);
		*out = eval_float(f);
		return 0;
	case KW_VNORMALIZE:
		f = sqrt(v[0][0] * v[0][0] + v[0][1] * v[0][1] + v[0][2] * v[0][2]);
		if (f == 0)
			eval_warning(e, n->loc, "vnormalize of a vector of length 0 gives <0, 0, 0>");
		for (int i = 0; i < 3; i++)
			r[i] = f == 0 ? 0 : v[0][i] / f;
		break;
	case KW_VCROSS:
		r[0] = v[0][1] * v[1][2] - v[0][2] * v[1][1];
		r[1] = v[0][2] * v[1][0] - v[0][0] * v[1][2];
		r[2] = v[0][0] * v[1][1] - v[0][1] * v[1][0];
		break;
	case KW_VROTATE: {
		xform t = scene_xform_rotate(v[1]);
		scene_xform_vector(&t, v[0], r);
		break;
	}
	default:   /* vaxis_rotate */
		if (eval_expect_float(e, n->kids[2], &f))
			return -1;
		if (v[1][0] == 0 && v[1][1] == 0 && v[1][2] == 0) {
			eval_error(e, n->kids[1]->loc, "vaxis_rotate() needs an axis that is not <0, 0, 0>");
			return -1;
		}
		axis_rotate(v[0], v[1], f, r);
		break;
	}
	*out = eval_vector3(r);
	return 0;
}

/* vturbulence(Lambda, Omega, Octaves, V): POV-Ray's DTurbulence at V, the
 * displacement a turbulence warp gives there, its octaves cut to 1..10 as
 * POV-Ray cuts them. */
static int vturbulence(struct eval *e, const ast_node *n, value *out)
{
	double a[3], v[3];
	if (nargs(e, n, 4, 4) || floats(e, n, a, 3) || eval_expect_vector(e, n->kids[3], v))
		return -1;
	int octaves = eval_int_of(a[2]);
	octaves = octaves < 1 ? 1 : octaves > 10 ? 10 : octaves;
	float p[3], r[3];
	for (int i = 0; i < 3; i++)   /* the device's bound on a warped point: float keeps it finite */
		p[i] = (float)fmin(fmax(v[i], -1e17), 1e17);
	scene_dturbulence(p, (float)a[1], (float)a[0], octaves, r);
	double d[3] = { r[0], r[1], r[2] };
	*out = eval_vector3(d);
	return 0;
}

/* min_extent(Object), max_extent(Object): the corners of the object's box. */
static int extent(struct eval *e, const ast_node *n, value *out)
{
	value v;
	if (n->n_kids != 1 || eval_expr(e, n->kids[0], &v))
		return -1;
	if (v.kind == V_OBJECT && v.obj->n_objs == 0 && v.obj->unsupported) {
		/* --skip-unsupported leaves the object out: it has no box to give */
		if (!e->opt->skip_unsupported) {
			eval_error(e, n->kids[0]->loc, "%s() of a '%s', which is not supported yet", ast_keyword_name(n->kw),
			           v.obj->unsupported);
			eval_value_free(&v);
			return -1;
		}
		eval_warn_once(e, n->loc, "extent of unsupported", "%s() of a '%s', which eclat leaves out, is <0, 0, 0>",
		               ast_keyword_name(n->kw), v.obj->unsupported);
		eval_value_free(&v);
		*out = eval_vector3((double[3]){ 0, 0, 0 });
		return 0;
	}
	if (v.kind != V_OBJECT || v.obj->n_objs == 0) {
		eval_error(e, n->kids[0]->loc, "%s() needs an object", ast_keyword_name(n->kw));
		eval_value_free(&v);
		return -1;
	}
	double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
	for (int i = 0; i < v.obj->n_objs; i++)
		scene_object_bounds(e->s, &v.obj->objs[i], lo, hi);
	eval_value_free(&v);
	*out = eval_vector3(n->kw == KW_MIN_EXTENT ? lo : hi);
	return 0;
}

static int builtin(struct eval *e, const ast_node *n, value *out)
{
	switch (n->kw) {
	case KW_STR: case KW_VSTR: case KW_CONCAT: case KW_SUBSTR: case KW_CHR: case KW_STRUPR: case KW_STRLWR:
		*out = (value){ .kind = V_STRING };
		return string_function(e, n, &out->str);
	case KW_VLENGTH: case KW_VDOT: case KW_VNORMALIZE: case KW_VCROSS: case KW_VROTATE: case KW_VAXIS_ROTATE:
		return vector_function(e, n, out);
	case KW_MIN_EXTENT: case KW_MAX_EXTENT:
		return extent(e, n, out);
	case KW_TRACE:
		return eval_trace(e, n, out);
	case KW_INSIDE:
		return eval_inside(e, n, out);
	case KW_VTURBULENCE:
		return vturbulence(e, n, out);
	default: {
		double r = 0;
		int rc = float_function(e, n, &r);
		if (rc == 0 && !isfinite(r)) {
			eval_error(e, n->loc, "%s() gives a result that is not a finite number", ast_keyword_name(n->kw));
			return -1;
		}
		*out = eval_float(r);
		return rc;
	}
	}
}

/* ---- calls ---- */

int eval_pattern_points(struct eval *e, src_loc loc, int pigment, bool colour, int n, const double *p, double *out)
{
	/* the globals the render will have, as far as the scene has read */
	scene *s = e->s;
	if (eval_pigment_has_object(s, pigment)) {   /* its object is lowered with the scene, after reading */
		eval_error(e, loc, "this pattern function holds an object pattern, which eclat runs on surfaces only, "
		           "not while it reads the scene");
		return -1;
	}
	int generator = s->noise_generator;
	float gamma = s->film_gamma;
	if (!e->noise_given)
		s->noise_generator = e->version < 3.5 ? 1 : 2;
	s->film_gamma = (float)eval_working_gamma(e);
	int rc = e->opt->pattern_at(e->opt->pattern_ctx, s, pigment, colour, n, p, out, loc);
	s->noise_generator = generator;
	s->film_gamma = gamma;
	return rc;
}

/* The point x, y, z a pattern, pigment or transform function is called at. */
static int point_arguments(struct eval *e, const ast_node *call, double p[3])
{
	if (call->n_kids != 3) {
		eval_error(e, call->loc, "function '%s' takes 3 arguments, not %d", call->str, call->n_kids);
		return -1;
	}
	for (int i = 0; i < 3; i++)
		if (eval_expect_float(e, call->kids[i], &p[i]))
			return -1;
	return 0;
}

/* A pattern function's value (a float) or a pigment function's colour at the
 * call's point, from the kernels (eval_pattern_points): POV-Ray evaluates
 * them wherever the scene calls them. Function patterns nested deeper than
 * the kernels' levels (function_pattern.cl) are refused here as they are in
 * the functions that call them. */
static int pattern_function(struct eval *e, const ast_node *call, const value *fn, bool colour, value *out)
{
	if (!e->opt->pattern_at) {
		eval_error(e, call->loc, "'%s' is a %s function, which this program cannot evaluate while it reads "
		           "the scene", call->str, colour ? "pigment" : "pattern");
		return -1;
	}
	double p[3], c[5] = { 0 };
	if (point_arguments(e, call, p))
		return -1;
	const scene_material *m = &fn->mat;
	int levels = m->pattern < 0 ? 0 : scene_pigment_levels(e->s, m->pattern);
	if (m->pattern < 0) {   /* a colour: a pattern function of it is 0, as POV-Ray's */
		for (int i = 0; colour && i < 5; i++)
			c[i] = m->pigment[i];
	} else if (levels >= SCENE_FUNCTION_LEVELS_MAX) {
		eval_error(e, call->loc, "'%s' runs function patterns nested %d deep, more than eclat's kernels run (%d)",
		           call->str, levels, SCENE_FUNCTION_LEVELS_MAX - 1);
		return -1;
	} else if (eval_pattern_points(e, call->loc, m->pattern, colour, 1, p, c)) {
		return -1;
	}
	if (!colour) {
		*out = eval_float(c[0]);
		return 0;
	}
	*out = (value){ .kind = V_COLOR, .n = 5 };
	memcpy(out->v, c, sizeof c);
	return 0;
}

/* function { transform { ... } }: the point x, y, z transformed, a vector
 * (POV-Ray's transform function; transforms.inc's vtransform calls one). */
static int transform_function(struct eval *e, const ast_node *call, const value *fn, const ast_node *b,
                              value *out)
{
	double p[3], q[3];
	if (point_arguments(e, call, p))
		return -1;
	ast_node item = { .kind = AST_BLOCK, .kw = KW_TRANSFORM, .loc = b->loc, .kids = b->kids, .n_kids = b->n_kids };
	xform t = scene_xform_identity();
	int pushed = eval_env_push(e, fn->env);
	int rc = eval_transform_item(e, NULL, &item, &t);
	eval_env_pop(e, pushed);
	if (rc < 0)
		return -1;
	scene_xform_point(&t, p, q);
	*out = eval_vector3(q);
	return 0;
}

/* An internal function that is one op (eval_internal_op) called while the
 * scene is read: the op on the arguments, f_noise3d with the noise_generator
 * global_settings has given so far (POV-Ray's default before). */
static int internal_op(struct eval *e, const ast_node *call, int op, int n_params, value *out)
{
	if (call->n_kids != n_params) {
		eval_error(e, call->loc, "function '%s' takes %d argument%s, not %d", call->str, n_params,
		           n_params == 1 ? "" : "s", call->n_kids);
		return -1;
	}
	double a[SCENE_FOP_ARITY_MAX];
	for (int i = 0; i < n_params; i++)
		if (eval_expect_float(e, call->kids[i], &a[i]))
			return -1;
	double v;
	if (op == FOP_NOISE3) {
		float p[3] = { (float)a[0], (float)a[1], (float)a[2] };
		v = scene_noise(p, e->noise_given ? e->s->noise_generator : e->version < 3.5 ? 1 : 2);
	} else {
		v = scene_fop_apply(op, a);
	}
	*out = eval_float(v);
	return 0;
}

/* function [(Params)] { Expression }: called with floats, gives a float. */
int eval_call_function(struct eval *e, const ast_node *call, const value *fn, value *out)
{
	const ast_node *def = fn->node, *params = def->kids[0], *body = def->kids[1];
	static const char *const xyz[] = { "x", "y", "z" };
	int n_params = params->n_kids ? params->n_kids : 3;
	if (body->n_kids != 1 || !AST_IS_EXPRESSION(body->kids[0]->kind)) {
		const ast_node *b = body->n_kids == 1 && body->kids[0]->kind == AST_BLOCK ? body->kids[0] : NULL;
		const char *what = !b ? "function" : b->kw == KW_PIGMENT ? "pigment" : b->str ? b->str : "function";
		if (b && b->kw == KW_TRANSFORM)
			return transform_function(e, call, fn, b, out);
		if (strcmp(what, "pigment") == 0 || strcmp(what, "pattern") == 0)
			return pattern_function(e, call, fn, what[1] == 'i', out);
		else
			eval_error(e, call->loc, "'%s' is a %s function, which eclat cannot evaluate", call->str, what);
		return -1;
	}
	if (body->kids[0]->kind == AST_CALL && strcmp(body->kids[0]->str, "internal") == 0) {
		/* eval_internal.c writes them in the function language: the host runs that too */
		const ast_node *number = body->kids[0]->n_kids == 1 ? body->kids[0]->kids[0] : NULL;
		double k = -1;
		int n_op = 0, op = number && number->kind == AST_NUMBER && number->num == (int)number->num ?
		                   eval_internal_op((int)number->num, &n_op) : -1;
		if (op >= 0)
			return internal_op(e, call, op, n_op, out);
		const ast_node *written = number && number->kind == AST_NUMBER ? eval_internal_function((int)(k = number->num))
		                        : NULL;
		if (!number || number->kind != AST_NUMBER) {
			eval_error(e, call->loc, "'%s' calls internal() with no number: it takes the number of one of "
			           "POV-Ray's internal functions, " EVAL_INTERNAL_RANGE, call->str);
			return -1;
		}
		if (!written || k != (int)k) {
			eval_error(e, call->loc, "'%s' is internal(%g), which is none of POV-Ray 3.7's internal functions "
			           "that eclat has: " EVAL_INTERNAL_RANGE, call->str, k);
			return -1;
		}
		value w = { .kind = V_FUNCTION, .node = written };
		return eval_call_function(e, call, &w, out);
	}
	if (call->n_kids != n_params) {
		eval_error(e, call->loc, "function '%s' takes %d argument%s, not %d", call->str, n_params,
		           n_params == 1 ? "" : "s", call->n_kids);
		return -1;
	}
	double a[64];
	for (int i = 0; i < n_params && i < 64; i++)
		if (eval_expect_float(e, call->kids[i], &a[i]))
			return -1;
	int pushed = eval_env_push(e, fn->env);
	int rc = eval_function_body(e, def, params->n_kids ? NULL : xyz, a, n_params, out);
	eval_env_pop(e, pushed);
	return rc;
}

static int call(struct eval *e, const ast_node *n, value *out)
{
	const value *v = eval_lookup(e, n->str);
	if (!v) {
		undeclared(e, n, "macro or function");
		return -1;
	}
	if (v->kind == V_MACRO) {
		value m = *v;   /* the symbol may change while the macro runs */
		return eval_macro_value(e, n, &m, out);
	}
	if (v->kind == V_FUNCTION) {
		value f = *v;
		return eval_call_function(e, n, &f, out);
	}
	if (v->kind == V_SPLINE) {
		value s = eval_value_copy(v);   /* the call's arguments may change the symbol */
		int rc = eval_spline_call(e, n, &s, out);
		eval_value_free(&s);
		return rc;
	}
	if (v->kind == V_OTHER)
		eval_error(e, n->loc, "'%s' is a %s, which eclat cannot evaluate yet", n->str, v->str);
	else
		eval_error(e, n->loc, "'%s' is %s, not a macro or a function", n->str, eval_kind_name(v->kind));
	return -1;
}

static int index_value(struct eval *e, const ast_node *n, value *out)
{
	int err = 0;
	const value *v = element(e, n, &err);
	if (!v)
		return -1;
	if (v->kind == V_NONE) {
		eval_error(e, n->loc, "this array element has no value yet");
		return -1;
	}
	*out = eval_value_copy(v);
	return 0;
}

static int expr(struct eval *e, const ast_node *n, value *out)
{
	switch (n->kind) {
	case AST_NUMBER: *out = eval_float(n->num); return 0;
	case AST_STRING: *out = (value){ .kind = V_STRING, .str = eval_xstrdup(n->str) }; return 0;
	case AST_IDENT: return identifier(e, n, out);
	case AST_VECTOR: return vector(e, n, out);
	case AST_BINARY: return binary(e, n, out);
	case AST_UNARY: return unary(e, n, out);
	case AST_COLOR: return color(e, n, out);
	case AST_COND: return conditional(e, n, out);
	case AST_MEMBER: return member(e, n, out);
	case AST_INDEX: return index_value(e, n, out);
	case AST_CALL: return call(e, n, out);
	case AST_FUNC: return builtin(e, n, out);
	case AST_IFEXPR: return eval_if_value(e, n, out);
	default:
		eval_error(e, n->loc, "expected an expression");
		return -1;
	}
}

int eval_expr(struct eval *e, const ast_node *n, value *out)
{
	static int depth;
	if (depth >= MAX_EXPR_DEPTH) {
		eval_error(e, n->loc, "expressions and macro calls nested more than %d deep", MAX_EXPR_DEPTH);
		return -1;
	}
	depth++;
	*out = (value){ .kind = V_NONE };
	int rc = e->stop ? -1 : expr(e, n, out);
	depth--;
	return rc;
}

/* ---- the types a place expects ---- */

static int type_error(struct eval *e, const ast_node *n, const char *want, value *v)
{
	eval_error(e, n->loc, "expected %s, found %s", want, eval_kind_name(v->kind));
	eval_value_free(v);
	return -1;
}

int eval_expect_float(struct eval *e, const ast_node *n, double *f)
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	if (v.kind != V_FLOAT)
		return type_error(e, n, "a float", &v);
	*f = v.v[0];
	return 0;
}

int eval_expect_int(struct eval *e, const ast_node *n, int *i)
{
	double f;
	if (eval_expect_float(e, n, &f))
		return -1;
	if (!(f > -2147483648.0 && f < 2147483648.0)) {
		eval_error(e, n->loc, "expected a whole number, found %g", f);
		return -1;
	}
	*i = (int)f;
	return 0;
}

/* A vector of 3 components; a float fills them, a vector of 2 gets a 0 (as in
 * POV-Ray). */
int eval_expect_vector(struct eval *e, const ast_node *n, double out[3])
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	if (v.kind != V_FLOAT && !(v.kind == V_VECTOR && v.n <= 3)) {
		if (v.kind == V_VECTOR)
			eval_error(e, n->loc, "expected a vector of 3 components, found %d components", v.n);
		else
			return type_error(e, n, "a vector", &v);
		return -1;
	}
	double w[5];
	eval_widen(&v, 3, w);
	for (int i = 0; i < 3; i++) {
		if (!isfinite(w[i])) {
			eval_error(e, n->loc, "vector component is not a finite number");
			return -1;
		}
		out[i] = w[i];
	}
	return 0;
}

int eval_expect_color(struct eval *e, const ast_node *n, double out[5])
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	if (!eval_is_numeric(v.kind))
		return type_error(e, n, "a colour", &v);
	eval_widen(&v, 5, out);
	return 0;
}

int eval_expect_kind(struct eval *e, const ast_node *n, val_kind kind, value *out)
{
	if (eval_expr(e, n, out))
		return -1;
	if (out->kind == kind)
		return 0;
	eval_error(e, n->loc, "expected %s, found %s", eval_kind_name(kind), eval_kind_name(out->kind));
	eval_value_free(out);
	return -1;
}

int eval_expect_string(struct eval *e, const ast_node *n, char **out)
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	if (v.kind != V_STRING)
		return type_error(e, n, "a string", &v);
	*out = v.str;
	return 0;
}
