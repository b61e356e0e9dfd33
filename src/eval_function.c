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
/* Whether the function being made may call pattern and pigment functions: a
 * pigment's function pattern or an isosurface may (the device runs it with
 * the scene's pattern buffers), and a height_field (its grid's points go to
 * the device at once); a parametric may not (the host refines its mesh one
 * point at a time). */
static bool patterns_allowed;

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
static int operands(struct fcomp *c, const ast_node *n, int first, int count);
static int add_once(scene *s, scene_function *f);

const ast_node *eval_function_pattern_body(const ast_node *def)
{
	const ast_node *body = def->kids[1];
	if (body->n_kids != 1 || body->kids[0]->kind != AST_BLOCK)
		return NULL;
	const ast_node *b = body->kids[0];
	if (b->kw == KW_PIGMENT || (b->kw == KW_UNKNOWN && b->str && strcmp(b->str, "pattern") == 0))
		return b;
	return NULL;
}

/* Whether a function that reads pigment would run function patterns nested
 * deeper than the kernels' levels (scene_function_levels). */
static bool too_deep(const scene *s, int pigment)
{
	return scene_pigment_levels(s, pigment) >= SCENE_FUNCTION_LEVELS_MAX;
}

/* Whether pigment's tree holds an object pattern, which only a surface's
 * patterns run (kernels/pattern.cl's pattern_at): a function's patterns are
 * read by pattern_plain, below the functions an object's isosurface may call,
 * and OpenCL C has no recursion. Pigments name earlier ones only. */
bool eval_pigment_has_object(const scene *s, int pigment)
{
	if (pigment < 0 || pigment >= s->n_pigments)
		return false;
	const scene_pigment *p = &s->pigments[pigment];
	if (p->kind == PATTERN_OBJECT)
		return true;
	for (int i = 0; i < p->n_map; i++)
		if (p->map[i].pigment < pigment && eval_pigment_has_object(s, p->map[i].pigment))
			return true;
	return false;
}

int eval_function_pigment(struct eval *e, const ast_node *def, scene_material *out)
{
	ast_node block = *eval_function_pattern_body(def);
	block.kw = KW_PIGMENT;   /* pattern { } reads as a pigment whose map goes unused */
	value v;
	if (eval_material_value(e, &block, &v))
		return -1;
	eval_value_free(&v);
	*out = v.mat;
	return 0;
}

int eval_function_pigment_pattern(struct eval *e, const ast_node *b, const char *instead, int *index)
{
	ast_node block = *b;
	block.kw = KW_PIGMENT;
	value v;
	if (eval_material_value(e, &block, &v))
		return -1;
	eval_value_free(&v);
	if (eval_pigment_has_object(e->s, v.mat.pattern)) {
		bool skipped = false;
		fallback = instead;
		unsupported(e, &skipped, b->loc, "this pigment_pattern's pigment holds an object pattern, which eclat "
		            "runs on surfaces only, not in functions");
		return skipped ? 1 : -1;
	}
	if (too_deep(e->s, v.mat.pattern)) {
		bool skipped = false;
		fallback = instead;
		unsupported(e, &skipped, b->loc, "this pigment_pattern's pigment runs function patterns nested %d "
		            "deep, more than eclat's kernels run (%d)", scene_pigment_levels(e->s, v.mat.pattern),
		            SCENE_FUNCTION_LEVELS_MAX - 1);
		return skipped ? 1 : -1;
	}
	scene_function f = { .n_params = 3, .loc = b->loc, .key = b };
	f.ops = eval_xrealloc(NULL, 4 * sizeof *f.ops);
	const float *c = v.mat.pigment;
	if (v.mat.pattern < 0) {   /* a colour: its grey, a constant */
		f.ops[f.n_ops++] = (scene_fop){ FOP_CONST, 0, 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2] };
	} else {
		for (int i = 0; i < 3; i++)
			f.ops[f.n_ops++] = (scene_fop){ FOP_PARAM, i, 0 };
		f.ops[f.n_ops++] = (scene_fop){ FOP_PIGMENT, v.mat.pattern, 5 };
	}
	*index = add_once(e->s, &f);
	return 0;
}

/* The pigment of the pattern or pigment function fn (evaluated where it was
 * declared, as POV-Ray does), called as name at use, if the function being
 * made may call it. */
static int function_pigment(struct fcomp *c, const value *fn, const char *name, src_loc use,
                            scene_material *out)
{
	if (!patterns_allowed)
		return unsupported(c->e, c->skipped, use, "'%s' is a pattern or pigment function, which a "
		                   "parametric's function cannot call yet (a pigment's function pattern, an isosurface's "
		                   "and a height_field's can)", name);
	if (eval_pigment_has_object(c->e->s, fn->mat.pattern))
		return unsupported(c->e, c->skipped, use, "'%s' holds an object pattern, which eclat runs on surfaces "
		                   "only, not in functions", name);
	if (too_deep(c->e->s, fn->mat.pattern))
		return unsupported(c->e, c->skipped, use, "'%s' runs function patterns nested %d deep, more than "
		                   "eclat's kernels run (%d)", name, scene_pigment_levels(c->e->s, fn->mat.pattern),
		                   SCENE_FUNCTION_LEVELS_MAX - 1);
	*out = fn->mat;
	return 0;
}

/* The channel a member of a pigment function's colour names (POV-Ray's
 * compile_member), or -1. */
static int channel_of(const char *m)
{
	static const char *const names[][3] = {
		{ "red", "x", "u" }, { "green", "y", "v" }, { "blue", "z", "" }, { "filter", "t", "" },
		{ "transmit", "", "" }, { "gray", "grey", "" },
	};
	for (int k = 0; k < 6; k++)
		for (int j = 0; j < 3; j++)
			if (names[k][j][0] && strcmp(m, names[k][j]) == 0)
				return k;
	return -1;
}

/* A call of a pattern function (channel -1) or of one channel of a pigment
 * function: its three arguments, then the op that reads the pigment. A
 * pigment without a pattern is its colour, a constant. */
static int pattern_call(struct fcomp *c, const ast_node *call, const value *fn, int channel)
{
	scene_material m;
	if (function_pigment(c, fn, call->str, call->loc, &m))
		return -1;
	if (call->n_kids != 3) {
		eval_error(c->e, call->loc, "function '%s' takes 3 arguments, not %d", call->str, call->n_kids);
		return -1;
	}
	if (m.pattern < 0) {
		const float *p = m.pigment;
		double v = channel < 0 ? 0 : channel < 5 ? p[channel] : 0.297 * p[0] + 0.589 * p[1] + 0.114 * p[2];
		return emit(c, call, FOP_CONST, 0, v);
	}
	if (operands(c, call, 0, 3))
		return -1;
	return channel < 0 ? emit(c, call, FOP_PATTERN, m.pattern, 0) : emit(c, call, FOP_PIGMENT, m.pattern, channel);
}

static int function_of(struct eval *e, const ast_node *def, struct scope *env, const char *name, src_loc use,
                       int depth, bool *skipped, int *index);

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
	const ast_node *block = eval_function_pattern_body(v->node);
	if (block)   /* a pigment function without a member: its red, as POV-Ray's first value */
		return pattern_call(c, n, v, block->kw == KW_PIGMENT ? 0 : -1);
	int callee;
	if (function_of(c->e, v->node, v->env, n->str, n->loc, c->depth + 1, c->skipped, &callee))
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
	case AST_MEMBER: {   /* P(x, y, z).x of a pigment function */
		const ast_node *k = n->kids[0];
		const value *v = k->kind == AST_CALL ? eval_lookup(c->e, k->str) : NULL;
		const ast_node *block = v && v->kind == V_FUNCTION ? eval_function_pattern_body(v->node) : NULL;
		if (block && block->kw == KW_PIGMENT) {
			int channel = channel_of(n->str);
			if (channel < 0) {
				eval_error(c->e, n->loc, "'.%s' is no member of a colour: red, green, blue, filter, transmit, "
				           "gray (or x, y, z, t, u, v)", n->str);
				return -1;
			}
			return pattern_call(c, k, v, channel);
		}
		if (k->kind == AST_CALL && call(c, k))
			return -1;
		eval_error(c->e, n->loc, "'.%s' of a float has no meaning in a function", n->str);
		return -1;
	}
	default:
		return unsupported(c->e, c->skipped, n->loc, "this expression of the function's parameters cannot be "
		                   "computed on the device (a function computes with floats)");
	}
}

/* f's index in the pool: an earlier function with the same program, or f
 * added. Programs, not definitions, are compared: a definition in a macro
 * makes a different program at each call when what it names differs. */
static int add_once(scene *s, scene_function *f)
{
	for (int i = 0; i < s->n_functions; i++) {
		const scene_function *g = &s->functions[i];
		if (g->n_params != f->n_params || g->n_ops != f->n_ops)
			continue;
		int k = 0;
		while (k < f->n_ops && g->ops[k].op == f->ops[k].op && g->ops[k].arg == f->ops[k].arg &&
		       memcmp(&g->ops[k].value, &f->ops[k].value, sizeof f->ops[k].value) == 0)
			k++;
		if (k == f->n_ops) {
			free(f->ops);
			return i;
		}
	}
	return scene_add_function(s, f);
}

/* internal(number) as its op, when it is one: 1 (and *index), else 0. */
static int op_internal(struct eval *e, const ast_node *def, int number, int *index)
{
	int n, op = eval_internal_op(number, &n);
	if (op >= 0) {
		scene_function f = { .n_params = n, .n_ops = n + 1, .loc = def->loc, .key = def };
		f.ops = eval_xrealloc(NULL, (size_t)(n + 1) * sizeof *f.ops);
		for (int i = 0; i < n; i++)
			f.ops[i] = (scene_fop){ FOP_PARAM, i, 0 };
		f.ops[n] = (scene_fop){ op, 0, 0 };
		*index = add_once(e->s, &f);
		return 1;
	}
	return 0;
}

/* env: the names def's body uses from where it was made (eval_capture). */
static int function_of(struct eval *e, const ast_node *def, struct scope *env, const char *name, src_loc use,
                       int depth, bool *skipped, int *index)
{
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
		if (op_internal(e, def, number, index))
			return 0;
		const ast_node *written = eval_internal_function(number);
		if (!written)
			return unsupported(e, skipped, use, "'%s' is internal(%d), which is none of POV-Ray 3.7's internal "
			                   "functions that eclat has: " EVAL_INTERNAL_RANGE, name, number);
		return function_of(e, written, NULL, name, use, depth + 1, skipped, index);
	}
	struct fcomp c = { .e = e, .def = def, .names = params->n_kids ? NULL : xyz,
	                   .n_params = params->n_kids ? params->n_kids : 3, .depth = depth, .skipped = skipped };
	c.f.n_params = c.n_params;
	c.f.loc = def->loc;
	c.f.key = def;
	int pushed = eval_env_push(e, env);
	int rc = compile(&c, body->kids[0]);
	eval_env_pop(e, pushed);
	if (rc) {
		free(c.f.ops);
		return -1;
	}
	*index = add_once(e->s, &c.f);
	return 0;
}

static int make(struct eval *e, const ast_node *def, const char *instead, bool patterns, int *index)
{
	/* a function pattern in a pigment read while this one is made (in a
	 * constant's expression) makes its own: this one's state comes back after */
	const char *was_fallback = fallback;
	bool was_allowed = patterns_allowed;
	bool skipped = false;
	fallback = instead;
	patterns_allowed = patterns;
	int rc = function_of(e, def, NULL, "function", def->loc, 0, &skipped, index);
	fallback = was_fallback;
	patterns_allowed = was_allowed;
	return rc && skipped ? 1 : rc;
}

int eval_function_index(struct eval *e, const ast_node *def, const char *instead, int *index)
{
	return make(e, def, instead, false, index);
}

int eval_function_pattern_index(struct eval *e, const ast_node *def, const char *instead, int *index)
{
	return make(e, def, instead, true, index);
}
