/* lower_function.c: the scene's functions (scene.functions) written as OpenCL
 * C, appended to the kernels' program when the scene has any
 * (kernels/function.cl declares what they define).
 *
 * The text comes from the ops alone: each op is one statement from the table
 * below, on numbered temporaries, and a constant is printed by printf from a
 * double. No name, string or text of the scene reaches the kernels' source, so
 * whatever a scene writes, the program is well-formed and does only
 * arithmetic, or calls a pattern or pigment function on a pattern tree
 * lowering made (roots: each scene pigment's dev_pattern). The host's twin is
 * scene_function_eval. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "lower.h"

/* Each op's expression on its operands #0, #1, ...: the same as apply() in
 * scene_function.c. */
static const char *const templates[FOP_COUNT] = {
	[FOP_NEG] = "-#0", [FOP_NOT] = "(#0 == 0 ? 1 : 0)",
	[FOP_ABS] = "fabs(#0)", [FOP_ACOS] = "acos(#0)", [FOP_ASIN] = "asin(#0)", [FOP_ATAN] = "atan(#0)",
	[FOP_ACOSH] = "acosh(#0)", [FOP_ASINH] = "asinh(#0)", [FOP_ATANH] = "atanh(#0)", [FOP_CEIL] = "ceil(#0)",
	[FOP_COS] = "cos(#0)", [FOP_COSH] = "cosh(#0)", [FOP_DEGREES] = "#0 * (real)57.295779513082323",
	[FOP_EXP] = "exp(#0)", [FOP_FLOOR] = "floor(#0)", [FOP_INT] = "trunc(#0)", [FOP_LN] = "log(#0)",
	[FOP_LOG] = "log10(#0)", [FOP_RADIANS] = "#0 * (real)0.017453292519943295", [FOP_SIN] = "sin(#0)",
	[FOP_SINH] = "sinh(#0)", [FOP_SQRT] = "sqrt(#0)", [FOP_TAN] = "tan(#0)", [FOP_TANH] = "tanh(#0)",
	[FOP_ADD] = "#0 + #1", [FOP_SUB] = "#0 - #1", [FOP_MUL] = "#0 * #1", [FOP_DIV] = "#0 / #1",
	[FOP_LT] = "(#0 < #1 ? 1 : 0)", [FOP_LE] = "(#0 <= #1 ? 1 : 0)", [FOP_GT] = "(#0 > #1 ? 1 : 0)",
	[FOP_GE] = "(#0 >= #1 ? 1 : 0)", [FOP_EQ] = "(#0 == #1 ? 1 : 0)", [FOP_NE] = "(#0 != #1 ? 1 : 0)",
	[FOP_AND] = "(#0 != 0 && #1 != 0 ? 1 : 0)", [FOP_OR] = "(#0 != 0 || #1 != 0 ? 1 : 0)",
	[FOP_MIN] = "fmin(#0, #1)", [FOP_MAX] = "fmax(#0, #1)", [FOP_ATAN2] = "atan2(#0, #1)",
	[FOP_POW] = "pow(#0, #1)", [FOP_MOD] = "fmod(#0, #1)", [FOP_IDIV] = "trunc(#0 / #1)",
	[FOP_COND] = "(#0 != 0 ? #1 : #2)", [FOP_SELECT3] = "(#0 < 0 ? #1 : #2)",
	[FOP_SELECT4] = "(#0 < 0 ? #1 : #0 == 0 ? #2 : #3)",
	[FOP_NOISE4] = "function_noise4(#0, #1, #2, #3)",
	[FOP_HETERO_MF] = "function_hetero_mf(#0, #1, #2, #3, #4, #5, #6, #7, #8)",
	[FOP_RIDGE] = "function_ridge(#0, #1, #2, #3, #4, #5, #6, #7, #8)",
	[FOP_RIDGED_MF] = "function_ridged_mf(#0, #1, #2, #3, #4, #5, #6, #7, #8)",
	[FOP_POLYTUBES] = "function_polytubes(#0, #1, #2, #3, #4, #5, #6, #7, #8)",
};

struct text {
	char *s;
	size_t len, cap;
	bool failed;
};

static void put(struct text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void put(struct text *t, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	if (t->failed || n < 0)
		return;
	if (t->len + n + 1 > t->cap) {
		size_t cap = (t->len + n + 1) * 2;
		char *s = realloc(t->s, cap);
		if (!s) {
			t->failed = true;
			return;
		}
		t->s = s;
		t->cap = cap;
	}
	va_start(ap, fmt);
	vsnprintf(t->s + t->len, t->cap - t->len, fmt, ap);
	va_end(ap);
	t->len += n;
}

/* Level L's names end in _L, level 1's in nothing (function_pattern.cl). */
static const char *suffix(int level, char buf[16])
{
	if (level <= 1)
		return "";
	snprintf(buf, 16, "_%d", level);
	return buf;
}

/* One op as "real tN = ...;" on the temporaries named by stack, in a function
 * of level L. */
static void statement(struct text *t, const scene *s, const int *roots, const scene_fop *o, int *stack, int *top,
                      int temp, int level)
{
	char buf[16];
	const char *sfx = suffix(level, buf);
	put(t, "\treal t%d = ", temp);
	if (o->op == FOP_CONST) {
		/* %g writes "inf" and "nan", which OpenCL C would read as names:
		 * evaluation refuses such constants, and here they are still numbers */
		if (isnan(o->value))
			put(t, "(real)NAN;\n");
		else if (isinf(o->value))
			put(t, "%s(real)INFINITY;\n", o->value < 0 ? "-" : "");
		else
			put(t, "(real)(%.17g);\n", o->value);
	} else if (o->op == FOP_PARAM) {
		put(t, "p%d;\n", o->arg);
	} else if (o->op == FOP_NOISE3) {
		*top -= 3;
		put(t, "(real)pattern_noise((float3)((float)t%d, (float)t%d, (float)t%d), %d);\n", stack[*top],
		    stack[*top + 1], stack[*top + 2], o->arg ? o->arg : s->noise_generator);
	} else if (o->op == FOP_PATTERN || o->op == FOP_PIGMENT) {
		*top -= 3;
		int root = roots ? roots[o->arg] : 0;
		/* sc is 0 only in raycast.cl's test kernels, which run no pattern */
		if (o->op == FOP_PATTERN)
			put(t, "sc ? function_pattern%s(sc, %d, ", sfx, root);
		else
			put(t, "sc ? function_pigment%s(sc, %d, %d, ", sfx, root, (int)o->value);
		put(t, "t%d, t%d, t%d) : (real)0;\n", stack[*top], stack[*top + 1], stack[*top + 2]);
	} else if (o->op == FOP_CALL) {
		int n = s->functions[o->arg].n_params;
		*top -= n;
		put(t, "scene_fn%d%s(sc", o->arg, sfx);
		for (int i = 0; i < n; i++)
			put(t, ", t%d", stack[*top + i]);
		put(t, ");\n");
	} else {
		int n = scene_fop_arity(o->op);
		*top -= n;
		for (const char *c = templates[o->op]; *c; c++) {
			if (c[0] == '#' && c[1] >= '0' && c[1] < '0' + n)
				put(t, "t%d", stack[*top + *++c - '0']);
			else
				put(t, "%c", *c);
		}
		put(t, ";\n");
	}
	stack[(*top)++] = temp;
}

static void function(struct text *t, const scene *s, const int *roots, int f, int level)
{
	char buf[16];
	const scene_function *fn = &s->functions[f];
	put(t, "static real scene_fn%d%s(const scene_data *sc", f, suffix(level, buf));
	for (int i = 0; i < fn->n_params; i++)
		put(t, ", real p%d", i);
	put(t, ")\n{\n");
	int stack[SCENE_FUNCTION_STACK], top = 0;
	for (int i = 0; i < fn->n_ops; i++)
		statement(t, s, roots, &fn->ops[i], stack, &top, i, level);
	if (top > 0)
		put(t, "\treturn t%d;\n}\n\n", stack[top - 1]);
	else
		put(t, "\treturn 0;\n}\n\n");
}

/* The program is what the ops promise (scene.h): eval_function.c makes it so,
 * and this keeps the text well-formed whatever hands it a program (the fuzz
 * target does): every op known, the stack within SCENE_FUNCTION_STACK and
 * never short, a parameter one of the function's, a call an earlier function. */
int lower_function_valid(const scene *s, int f, char *why, size_t n)
{
	const scene_function *fn = &s->functions[f];
	if (fn->n_params < 0 || fn->n_params > SCENE_FUNCTION_STACK || fn->n_ops < 0) {
		snprintf(why, n, "%d parameters and %d ops", fn->n_params, fn->n_ops);
		return 0;
	}
	int top = 0;
	for (int i = 0; i < fn->n_ops; i++) {
		const scene_fop *o = &fn->ops[i];
		int pop = o->op == FOP_CALL && o->arg >= 0 && o->arg < f ? s->functions[o->arg].n_params
		        : scene_fop_arity(o->op);
		bool pattern = o->op == FOP_PATTERN || o->op == FOP_PIGMENT;
		if (o->op < 0 || o->op >= FOP_COUNT ||
		    (o->op > FOP_CALL && o->op != FOP_NOISE3 && !pattern && !templates[o->op]))
			snprintf(why, n, "op %d is %d, no op", i, o->op);
		else if (pattern && (o->arg < 0 || o->arg >= s->n_pigments || !(o->value >= 0 && o->value <= 5)))
			snprintf(why, n, "op %d reads pigment %d channel %g of %d pigments", i, o->arg, o->value,
			         s->n_pigments);
		else if (o->op == FOP_PARAM && (o->arg < 0 || o->arg >= fn->n_params))
			snprintf(why, n, "op %d reads parameter %d of %d", i, o->arg, fn->n_params);
		else if (o->op == FOP_CALL && (o->arg < 0 || o->arg >= f))
			snprintf(why, n, "op %d calls function %d, not an earlier one", i, o->arg);
		else if (pop > top)
			snprintf(why, n, "op %d takes %d values from a stack of %d", i, pop, top);
		else if (top - pop + 1 > SCENE_FUNCTION_STACK)
			snprintf(why, n, "op %d makes the stack deeper than %d", i, SCENE_FUNCTION_STACK);
		else {
			top += 1 - pop;
			continue;
		}
		return 0;
	}
	return 1;
}

int *lower_function_roots(lower_textures *lt, const scene *s)
{
	int *roots = NULL;
	for (int f = 0; f < s->n_functions; f++)
		for (int i = 0; i < s->functions[f].n_ops; i++) {
			const scene_fop *o = &s->functions[f].ops[i];
			if ((o->op != FOP_PATTERN && o->op != FOP_PIGMENT) || o->arg < 0 || o->arg >= s->n_pigments)
				continue;
			if (!roots) {
				roots = malloc((size_t)s->n_pigments * sizeof *roots);
				if (!roots)
					return NULL;
				for (int k = 0; k < s->n_pigments; k++)
					roots[k] = -1;
			}
			if (roots[o->arg] < 0)
				roots[o->arg] = lower_texture_pigment(lt, s, o->arg);
		}
	return roots;
}

/* The function patterns in pigment pg's tree: their functions are needed at
 * the level below (row). */
static void mark_pigment(const scene *s, int pg, bool *row, int depth)
{
	if (pg < 0 || pg >= s->n_pigments || depth > 64)
		return;
	const scene_pigment *p = &s->pigments[pg];
	int f = (int)p->params[0][0];
	if (p->kind == PATTERN_FUNCTION && f >= 0 && f < s->n_functions)
		row[f] = true;
	for (int i = 0; i < p->n_map; i++)
		mark_pigment(s, p->map[i].pigment, row, depth + 1);
}

/* Which functions each level needs (levels rows of n_functions): level 1
 * all of them (patterns, isosurfaces and the host's points call any); level
 * L + 1 those of the function patterns that level L's functions read, and
 * what they call. A level's copies are only those, so that a nest does not
 * multiply the program by every function at every level. */
static bool *needed(const scene *s, int levels, int read)
{
	int n = s->n_functions;
	bool *need = calloc((size_t)levels * n + 1, sizeof *need);
	if (!need)
		return NULL;
	for (int f = 0; f < n; f++)
		need[f] = true;
	if (levels > 1)
		mark_pigment(s, read, need + n, 0);
	for (int level = 1; level <= levels; level++) {
		bool *row = need + (size_t)(level - 1) * n, *next = level < levels ? row + n : NULL;
		for (int f = n - 1; f >= 0; f--) {   /* callers first: a call names an earlier function */
			if (!row[f])
				continue;
			const scene_function *fn = &s->functions[f];
			for (int i = 0; i < fn->n_ops; i++) {
				const scene_fop *o = &fn->ops[i];
				if (o->op == FOP_CALL && o->arg >= 0 && o->arg < f)
					row[o->arg] = true;
				else if ((o->op == FOP_PATTERN || o->op == FOP_PIGMENT) && next)
					mark_pigment(s, o->arg, next, 0);
			}
		}
	}
	return need;
}

int lower_function_levels(const scene *s)
{
	int most = 1;
	for (int f = 0; f < s->n_functions; f++) {
		int l = scene_function_levels(s, f);
		most = l > most ? l : most;
	}
	return most;
}

char *lower_function_source(const scene *s, const int *roots)
{
	return lower_function_source_reading(s, roots, -1);
}

char *lower_function_source_reading(const scene *s, const int *roots, int read)
{
	if (s->n_functions == 0)
		return NULL;
	for (int f = 0; f < s->n_functions; f++) {
		char why[128];
		if (!lower_function_valid(s, f, why, sizeof why)) {
			diag_error(s->functions[f].loc, "the function's program is malformed (%s): eclat's error, "
			           "not the scene's", why);
			return NULL;
		}
	}
	int levels = lower_function_levels(s), below = 1 + scene_pigment_levels(s, read);
	levels = below > levels ? below : levels;
	if (levels > SCENE_FUNCTION_LEVELS_MAX) {
		diag_error(SRC_NOWHERE, "the scene's functions run function patterns nested %d deep, more than the "
		           "kernels' %d: eclat's error, not the scene's", levels, SCENE_FUNCTION_LEVELS_MAX);
		return NULL;
	}
	struct text t = { 0 };
	put(&t, "/* The scene's functions, written by src/lower_function.c. */\n");
	/* the deeper levels' pattern readers (function_pattern.cl's macros) */
	for (int level = 2; level <= levels; level++) {
		if (level < levels)
			put(&t, "FUNCTION_PATTERN_AT(%d)\nFUNCTION_PATTERN_LEVEL(_%d, pattern_at_%d)\n", level + 1, level,
			    level + 1);
		else
			put(&t, "FUNCTION_PATTERN_LEVEL(_%d, function_plain_at)\n", level);
	}
	bool *need = needed(s, levels, read);
	if (!need)
		return NULL;
	for (int level = 1; level <= levels; level++) {
		char buf[16];
		const char *sfx = suffix(level, buf);
		const bool *here = need + (size_t)(level - 1) * s->n_functions;
		for (int f = 0; f < s->n_functions; f++)
			if (here[f])
				function(&t, s, roots, f, level);
		put(&t, "static real scene_function_at%s(const scene_data *sc, int f, real x, real y, real z)\n{\n"
		    "\tswitch (f) {\n", sfx);
		for (int f = 0; f < s->n_functions; f++) {
			if (!here[f])
				continue;
			put(&t, "\tcase %d: return scene_fn%d%s(sc", f, f, sfx);
			for (int i = 0; i < s->functions[f].n_params; i++)
				put(&t, ", %s", i == 0 ? "x" : i == 1 ? "y" : i == 2 ? "z" : "0");
			put(&t, ");\n");
		}
		put(&t, "\t}\n\treturn 0;\n}\n");
	}
	free(need);
	if (t.failed) {
		free(t.s);
		return NULL;
	}
	return t.s;
}
