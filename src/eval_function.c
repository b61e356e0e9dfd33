/* eval_function.c: a POV-Ray function { } made into a program the device runs
 * (scene.h, scene_function), for function patterns.
 *
 * The host evaluates a function by walking its syntax tree in a scope of its
 * parameters (eval_call_function). The device cannot: there the function
 * becomes postfix ops, and lowering writes those as OpenCL C. Everything in
 * the body that does not depend on a parameter is computed here, once, by the
 * host evaluator (declared floats, pi, clock, a vector's component, rand()):
 * it becomes a constant. What depends on a parameter must be arithmetic,
 * comparisons, the math functions, select() and calls of other functions; a
 * called function becomes a function of the pool, made once. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

/* How deep functions may call functions: POV-Ray's cannot recurse (a function
 * names only those declared before it), eclat's lookup at call time could. */
#define MAX_CALL_DEPTH 32

struct fcomp {
	struct eval *e;
	const ast_node *def;
	const char *const *names;  /* the parameters' names, NULL: def's */
	int n_params;
	scene_function f;
	int cap, top;              /* ops allocated; the stack's height after them */
	int depth;                 /* of calls: this function's */
	bool *skipped;             /* set when --skip-unsupported turned an error into a warning */
};

/* What --skip-unsupported does instead, for its warning: "the pattern is averaged". */
static const char *fallback;

static const char *const xyz[] = { "x", "y", "z" };

/* What eclat cannot run on the device yet (not what is wrong in the scene):
 * an error, or with --skip-unsupported a warning, and the pattern is averaged. */
static int unsupported(struct eval *e, bool *skipped, src_loc loc, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));

static int unsupported(struct eval *e, bool *skipped, src_loc loc, const char *fmt, ...)
{
	char msg[256];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (!e->opt->skip_unsupported) {
		eval_error(e, loc, "%s", msg);
	} else {
		eval_warn_once(e, loc, msg, "%s; %s", msg, fallback);
		*skipped = true;
	}
	return -1;
}

static int param_index(const struct fcomp *c, const char *name)
{
	/* a function without a parameter list calls x and y u and v too, as
	 * POV-Ray's do (a parametric's functions are written in u and v) */
	if (c->names == xyz && (strcmp(name, "u") == 0 || strcmp(name, "v") == 0))
		return name[0] == 'u' ? 0 : 1;
	for (int i = 0; i < c->n_params; i++)
		if (strcmp(c->names ? c->names[i] : c->def->kids[0]->kids[i]->str, name) == 0)
			return i;
	return -1;
}

/* Whether n's value depends on the parameters: a parameter in it, or a call
 * of a function (made on the device, never folded). */
static bool depends(const struct fcomp *c, const ast_node *n)
{
	if (n->kind == AST_IDENT)
		return param_index(c, n->str) >= 0;
	if (n->kind == AST_CALL) {
		const value *v = eval_lookup(c->e, n->str);
		if (v && v->kind == V_FUNCTION)
			return true;
	}
	for (int i = 0; i < n->n_kids; i++)
		if (depends(c, n->kids[i]))
			return true;
	return false;
}

static int emit(struct fcomp *c, const ast_node *at, int op, int arg, double v)
{
	int pops = op == FOP_CONST || op == FOP_PARAM ? 0
	         : op == FOP_CALL ? c->e->s->functions[arg].n_params : scene_fop_arity(op);
	c->top += 1 - pops;
	if (c->top > SCENE_FUNCTION_STACK) {
		eval_error(c->e, at->loc, "this function is nested too deeply for the device (more than %d values "
		           "pending at once)", SCENE_FUNCTION_STACK);
		return -1;
	}
	if (c->e->s->n_fops + c->f.n_ops >= SCENE_MAX_FOPS) {
		eval_error(c->e, at->loc, "the scene's functions have more than %d operations in all", SCENE_MAX_FOPS);
		return -1;
	}
	if (c->f.n_ops == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 32;
		c->f.ops = eval_xrealloc(c->f.ops, c->cap * sizeof *c->f.ops);
	}
	c->f.ops[c->f.n_ops++] = (scene_fop){ op, arg, v };
	return 0;
}

static int compile(struct fcomp *c, const ast_node *n);

static int function_of(struct eval *e, const ast_node *def, const char *name, src_loc use, int depth, bool *skipped,
                       int *index);

static int operands(struct fcomp *c, const ast_node *n, int first, int count)
{
	for (int i = first; i < first + count; i++)
		if (compile(c, n->kids[i]))
			return -1;
	return 0;
}

static int binary(struct fcomp *c, const ast_node *n)
{
	int op;
	switch (n->op) {
	case '+': op = FOP_ADD; break;
	case '-': op = FOP_SUB; break;
	case '*': op = FOP_MUL; break;
	case '/': op = FOP_DIV; break;
	case '<': op = FOP_LT; break;
	case '>': op = FOP_GT; break;
	case '=': op = FOP_EQ; break;
	case '&': op = FOP_AND; break;
	case '|': op = FOP_OR; break;
	case OP_LE: op = FOP_LE; break;
	case OP_GE: op = FOP_GE; break;
	case OP_NE: op = FOP_NE; break;
	default:
		eval_error(c->e, n->loc, "the operator '%s' has no meaning in a function", ast_op_name(n->op));
		return -1;
	}
	return operands(c, n, 0, 2) || emit(c, n, op, 0, 0) ? -1 : 0;
}

/* The math functions of one float and their ops. */
static int math1_op(int kw)
{
	switch (kw) {
	case KW_ABS: return FOP_ABS;
	case KW_ACOS: return FOP_ACOS;
	case KW_ASIN: return FOP_ASIN;
	case KW_ATAN: return FOP_ATAN;
	case KW_ACOSH: return FOP_ACOSH;
	case KW_ASINH: return FOP_ASINH;
	case KW_ATANH: return FOP_ATANH;
	case KW_CEIL: return FOP_CEIL;
	case KW_COS: return FOP_COS;
	case KW_COSH: return FOP_COSH;
	case KW_DEGREES: return FOP_DEGREES;
	case KW_EXP: return FOP_EXP;
	case KW_FLOOR: return FOP_FLOOR;
	case KW_INT: return FOP_INT;
	case KW_LN: return FOP_LN;
	case KW_LOG: return FOP_LOG;
	case KW_RADIANS: return FOP_RADIANS;
	case KW_SIN: return FOP_SIN;
	case KW_SINH: return FOP_SINH;
	case KW_SQRT: return FOP_SQRT;
	case KW_TAN: return FOP_TAN;
	case KW_TANH: return FOP_TANH;
	default: return -1;
	}
}

static int builtin(struct fcomp *c, const ast_node *n)
{
	const char *name = ast_keyword_name(n->kw);
	int op = math1_op(n->kw), want = 1;
	switch (n->kw) {
	case KW_ATAN2: op = FOP_ATAN2; want = 2; break;
	case KW_POW: op = FOP_POW; want = 2; break;
	case KW_MOD: op = FOP_MOD; want = 2; break;
	case KW_DIV: op = FOP_IDIV; want = 2; break;
	case KW_SELECT: op = n->n_kids == 4 ? FOP_SELECT4 : FOP_SELECT3; want = n->n_kids == 4 ? 4 : 3; break;
	case KW_MIN: case KW_MAX:
		if (n->n_kids < 1) {
			eval_error(c->e, n->loc, "%s() takes at least one argument", name);
			return -1;
		}
		if (compile(c, n->kids[0]))
			return -1;
		for (int i = 1; i < n->n_kids; i++)
			if (compile(c, n->kids[i]) || emit(c, n, n->kw == KW_MIN ? FOP_MIN : FOP_MAX, 0, 0))
				return -1;
		return 0;
	default:
		break;
	}
	if (op < 0)
		return unsupported(c->e, c->skipped, n->loc, "%s() of the function's parameters cannot be computed on "
		                   "the device", name);
	if (n->n_kids != want) {
		eval_error(c->e, n->loc, "%s() takes %d argument%s, not %d", name, want, want == 1 ? "" : "s", n->n_kids);
		return -1;
	}
	return operands(c, n, 0, want) || emit(c, n, op, 0, 0) ? -1 : 0;
}

static int call(struct fcomp *c, const ast_node *n)
{
	const value *v = eval_lookup(c->e, n->str);
	if (!v || v->kind != V_FUNCTION) {
		eval_error(c->e, n->loc, "'%s' is not a function", n->str);
		return -1;
	}
	int callee;
	if (function_of(c->e, v->node, n->str, n->loc, c->depth + 1, c->skipped, &callee))
		return -1;
	int want = c->e->s->functions[callee].n_params;
	if (n->n_kids != want) {
		eval_error(c->e, n->loc, "function '%s' takes %d argument%s, not %d", n->str, want, want == 1 ? "" : "s",
		           n->n_kids);
		return -1;
	}
	return operands(c, n, 0, want) || emit(c, n, FOP_CALL, callee, 0) ? -1 : 0;
}

static int compile(struct fcomp *c, const ast_node *n)
{
	if (!depends(c, n)) {   /* a constant: the host computes it now */
		value v;
		if (eval_expr(c->e, n, &v))
			return -1;
		if (v.kind != V_FLOAT) {
			eval_error(c->e, n->loc, "a function computes with floats; this is %s", eval_kind_name(v.kind));
			eval_value_free(&v);
			return -1;
		}
		if (!isfinite(v.v[0])) {
			eval_error(c->e, n->loc, "this value is not a finite number");
			return -1;
		}
		return emit(c, n, FOP_CONST, 0, v.v[0]);
	}
	switch (n->kind) {
	case AST_IDENT:
		return emit(c, n, FOP_PARAM, param_index(c, n->str), 0);
	case AST_UNARY:
		if (compile(c, n->kids[0]))
			return -1;
		return n->op == '-' ? emit(c, n, FOP_NEG, 0, 0) : n->op == '!' ? emit(c, n, FOP_NOT, 0, 0) : 0;
	case AST_BINARY:
		return binary(c, n);
	case AST_COND:
		return operands(c, n, 0, 3) || emit(c, n, FOP_COND, 0, 0) ? -1 : 0;
	case AST_FUNC:
		return builtin(c, n);
	case AST_CALL:
		return call(c, n);
	case AST_MEMBER:   /* P(x, y, z).x of a pigment function: say so */
		if (n->kids[0]->kind == AST_CALL && call(c, n->kids[0]))
			return -1;
		eval_error(c->e, n->loc, "'.%s' of a float has no meaning in a function", n->str);
		return -1;
	default:
		return unsupported(c->e, c->skipped, n->loc, "this expression of the function's parameters cannot be "
		                   "computed on the device (a function computes with floats)");
	}
}

/* The pool's function made from def, made now unless it was before. name: how
 * the scene calls it (for messages), use: where. */
/* f_noise3d, internal(76): POV-Ray's Noise at (x, y, z) with the scene's
 * noise_generator (global_settings may come later: 0 stands for it). */
#define NOISE3D 76
static int noise3d(struct eval *e, const ast_node *def, int *index)
{
	scene_function f = { .n_params = 3, .n_ops = 4, .loc = def->loc, .key = def };
	f.ops = eval_xrealloc(NULL, 4 * sizeof *f.ops);
	for (int i = 0; i < 3; i++)
		f.ops[i] = (scene_fop){ FOP_PARAM, i, 0 };
	f.ops[3] = (scene_fop){ FOP_NOISE3, 0, 0 };
	*index = scene_add_function(e->s, &f);
	return 0;
}

static int function_of(struct eval *e, const ast_node *def, const char *name, src_loc use, int depth, bool *skipped,
                       int *index)
{
	for (int i = 0; i < e->s->n_functions; i++)
		if (e->s->functions[i].key == def) {
			*index = i;
			return 0;
		}
	if (depth > MAX_CALL_DEPTH) {
		eval_error(e, use, "functions call each other more than %d deep here (a function that calls itself?)",
		           MAX_CALL_DEPTH);
		return -1;
	}
	const ast_node *params = def->kids[0], *body = def->kids[1];
	if (body->n_kids != 1 || !AST_IS_EXPRESSION(body->kids[0]->kind))
		return unsupported(e, skipped, use, "'%s' is a pattern or pigment function, which the device cannot run "
		                   "yet", name);
	if (body->kids[0]->kind == AST_CALL && strcmp(body->kids[0]->str, "internal") == 0) {
		const ast_node *call = body->kids[0];
		int number;
		if (call->n_kids != 1 || eval_expect_int(e, call->kids[0], &number))
			return -1;
		if (number == NOISE3D)
			return noise3d(e, def, index);
		const ast_node *written = eval_internal_function(number);
		if (!written)
			return unsupported(e, skipped, use, "'%s' is one of POV-Ray's internal functions (internal(%d)), "
			                   "which eclat does not have yet", name, number);
		return function_of(e, written, name, use, depth + 1, skipped, index);
	}
	struct fcomp c = { .e = e, .def = def, .names = params->n_kids ? NULL : xyz,
	                   .n_params = params->n_kids ? params->n_kids : 3, .depth = depth, .skipped = skipped };
	c.f.n_params = c.n_params;
	c.f.loc = def->loc;
	c.f.key = def;
	if (compile(&c, body->kids[0])) {
		free(c.f.ops);
		return -1;
	}
	*index = scene_add_function(e->s, &c.f);
	return 0;
}

int eval_function_index(struct eval *e, const ast_node *def, const char *instead, int *index)
{
	bool skipped = false;
	fallback = instead;
	int rc = function_of(e, def, "function", def->loc, 0, &skipped, index);
	return rc && skipped ? 1 : rc;
}
