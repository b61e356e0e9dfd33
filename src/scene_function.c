/* scene_function.c: the pool of POV-Ray functions made into programs
 * (scene.h, scene_function), and their host evaluation: the same ops, in the
 * same order, as the OpenCL that lowering writes, in double. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

static const struct {
	const char *name;
	int arity;
} fops[] = {
#define X(name, arity) { #name, arity },
	SCENE_FOPS(X)
#undef X
};

int scene_fop_arity(int op)
{
	return op >= 0 && op < FOP_COUNT ? fops[op].arity : 0;
}

const char *scene_fop_name(int op)
{
	return op >= 0 && op < FOP_COUNT ? fops[op].name : "?";
}

int scene_add_function(scene *s, const scene_function *f)
{
	if (s->n_functions == s->cap_functions) {
		int cap = s->cap_functions ? 2 * s->cap_functions : 8;
		scene_function *p = realloc(s->functions, cap * sizeof *p);
		if (!p)
			abort();
		s->functions = p;
		s->cap_functions = cap;
	}
	s->functions[s->n_functions] = *f;
	s->n_fops += f->n_ops;
	return s->n_functions++;
}

static double truth(bool b)
{
	return b ? 1.0 : 0.0;
}

/* f_polytubes (internal(52)): x y z, then the number of tubes and the
 * coefficients of their distance from the y axis, a polynomial of y; as
 * kernels/function.cl's function_polytubes. POV-Ray loops (int)P0 tubes, a
 * cast undefined past int or for NaN: here at most SCENE_TUBES_MAX, and none
 * for NaN. */
#define SCENE_TUBES_MAX 256.0
static double polytubes(const double *a)
{
	double x = a[0], y = a[1], z = a[2], tubes = a[3], y2 = y * y;
	double radius = a[4] + a[5] * y + a[6] * y2 + a[7] * y2 * y + a[8] * y2 * y2;
	int n = tubes > 0 ? (int)fmin(tubes, SCENE_TUBES_MAX) : 0;
	double r = -10000;
	for (int i = 0; i < n; i++) {
		double dx = x - radius * sin(2 * M_PI / tubes * i), dz = z - radius * cos(2 * M_PI / tubes * i);
		r = fmax(r, -sqrt(dx * dx + dz * dz));
	}
	return -r;
}

/* One op on its operands a[0 .. arity - 1]. */
double scene_fop_apply(int op, const double *a)
{
	switch (op) {
	case FOP_NEG: return -a[0];
	case FOP_NOT: return truth(a[0] == 0);
	case FOP_ABS: return fabs(a[0]);
	case FOP_ACOS: return acos(a[0]);
	case FOP_ASIN: return asin(a[0]);
	case FOP_ATAN: return atan(a[0]);
	case FOP_ACOSH: return acosh(a[0]);
	case FOP_ASINH: return asinh(a[0]);
	case FOP_ATANH: return atanh(a[0]);
	case FOP_CEIL: return ceil(a[0]);
	case FOP_COS: return cos(a[0]);
	case FOP_COSH: return cosh(a[0]);
	case FOP_DEGREES: return a[0] * (180.0 / M_PI);
	case FOP_EXP: return exp(a[0]);
	case FOP_FLOOR: return floor(a[0]);
	case FOP_INT: return trunc(a[0]);
	case FOP_LN: return log(a[0]);
	case FOP_LOG: return log10(a[0]);
	case FOP_RADIANS: return a[0] * (M_PI / 180.0);
	case FOP_SIN: return sin(a[0]);
	case FOP_SINH: return sinh(a[0]);
	case FOP_SQRT: return sqrt(a[0]);
	case FOP_TAN: return tan(a[0]);
	case FOP_TANH: return tanh(a[0]);
	case FOP_ADD: return a[0] + a[1];
	case FOP_SUB: return a[0] - a[1];
	case FOP_MUL: return a[0] * a[1];
	case FOP_DIV: return a[0] / a[1];
	case FOP_LT: return truth(a[0] < a[1]);
	case FOP_LE: return truth(a[0] <= a[1]);
	case FOP_GT: return truth(a[0] > a[1]);
	case FOP_GE: return truth(a[0] >= a[1]);
	case FOP_EQ: return truth(a[0] == a[1]);
	case FOP_NE: return truth(a[0] != a[1]);
	case FOP_AND: return truth(a[0] != 0 && a[1] != 0);
	case FOP_OR: return truth(a[0] != 0 || a[1] != 0);
	case FOP_MIN: return fmin(a[0], a[1]);
	case FOP_MAX: return fmax(a[0], a[1]);
	case FOP_ATAN2: return atan2(a[0], a[1]);
	case FOP_POW: return pow(a[0], a[1]);
	case FOP_MOD: return fmod(a[0], a[1]);
	case FOP_IDIV: return trunc(a[0] / a[1]);
	case FOP_COND: return a[0] != 0 ? a[1] : a[2];
	case FOP_SELECT3: return a[0] < 0 ? a[1] : a[2];
	case FOP_SELECT4: return a[0] < 0 ? a[1] : a[0] == 0 ? a[2] : a[3];
	case FOP_NOISE4: case FOP_HETERO_MF: case FOP_RIDGE: case FOP_RIDGED_MF: return scene_noise_op(op, a);
	case FOP_POLYTUBES: return polytubes(a);
	default: return 0;
	}
}

/* The programs are checked when made (eval_function.c): the stack stays within
 * SCENE_FUNCTION_STACK and a call names an earlier function, so this recursion
 * is as deep as the chain of calls. */
double scene_function_eval(const scene *s, int f, const double *args)
{
	const scene_function *fn = &s->functions[f];
	double stack[SCENE_FUNCTION_STACK];
	int top = 0;
	for (int i = 0; i < fn->n_ops; i++) {
		const scene_fop *o = &fn->ops[i];
		if (o->op == FOP_CONST) {
			stack[top++] = o->value;
		} else if (o->op == FOP_PARAM) {
			stack[top++] = args[o->arg];
		} else if (o->op == FOP_NOISE3) {
			top -= 3;
			float p[3] = { (float)stack[top], (float)stack[top + 1], (float)stack[top + 2] };
			stack[top++] = scene_noise(p, o->arg ? o->arg : s->noise_generator);
		} else if (o->op == FOP_CALL) {
			int n = s->functions[o->arg].n_params;
			top -= n;
			stack[top] = scene_function_eval(s, o->arg, stack + top);
			top++;
		} else {
			int n = fops[o->op].arity;
			top -= n;
			stack[top] = scene_fop_apply(o->op, stack + top);
			top++;
		}
	}
	return top > 0 ? stack[top - 1] : 0;
}

/* A pattern or pigment op's values at the n points of its three operands'
 * columns, into the first column: the pattern's value, or one channel of the
 * colour (5: POV-Ray's grey, the weights of function_pigment). */
static int pattern_op(const scene_fop *o, int n, double *col[3], scene_pattern_points pattern, void *ctx)
{
	if (!pattern) {
		for (int i = 0; i < n; i++)
			col[0][i] = 0;
		return 0;
	}
	double *p = malloc((size_t)n * 8 * sizeof *p), *c = p + 3 * n;
	if (!p)
		return -1;
	for (int i = 0; i < n; i++)
		for (int k = 0; k < 3; k++)
			p[3 * i + k] = col[k][i];
	bool colour = o->op == FOP_PIGMENT;
	int channel = colour ? (int)o->value : 0;
	int rc = pattern(ctx, o->arg, colour, n, p, c);
	for (int i = 0; i < n && rc == 0; i++) {
		const double *v = c + 5 * i;
		col[0][i] = channel < 5 ? v[channel] : (double)(0.297f * (float)v[0] + 0.589f * (float)v[1] +
		                                                0.114f * (float)v[2]);
	}
	free(p);
	return rc;
}

/* The stack holds a column of n values a slot. */
int scene_function_eval_many(const scene *s, int f, int n, const double *args, double *out,
                             scene_pattern_points pattern, void *ctx)
{
	const scene_function *fn = &s->functions[f];
	double *stack = malloc((size_t)SCENE_FUNCTION_STACK * n * sizeof *stack);
	if (!stack)
		return -1;
	double *col[SCENE_FUNCTION_STACK];
	for (int k = 0; k < SCENE_FUNCTION_STACK; k++)
		col[k] = stack + (size_t)k * n;
	int top = 0, rc = 0;
	for (int j = 0; j < fn->n_ops && rc == 0; j++) {
		const scene_fop *o = &fn->ops[j];
		if (o->op == FOP_CONST) {
			for (int i = 0; i < n; i++)
				col[top][i] = o->value;
		} else if (o->op == FOP_PARAM) {
			for (int i = 0; i < n; i++)
				col[top][i] = args[(size_t)i * fn->n_params + o->arg];
		} else if (o->op == FOP_NOISE3) {
			top -= 3;
			for (int i = 0; i < n; i++) {
				float p[3] = { (float)col[top][i], (float)col[top + 1][i], (float)col[top + 2][i] };
				col[top][i] = scene_noise(p, o->arg ? o->arg : s->noise_generator);
			}
		} else if (o->op == FOP_PATTERN || o->op == FOP_PIGMENT) {
			top -= 3;
			rc = pattern_op(o, n, col + top, pattern, ctx);
		} else if (o->op == FOP_CALL) {
			int k = s->functions[o->arg].n_params;
			top -= k;
			double *a = malloc(((size_t)n * k + 1) * sizeof *a);
			if (!a) {
				rc = -1;
				break;
			}
			for (int i = 0; i < n; i++)
				for (int m = 0; m < k; m++)
					a[(size_t)i * k + m] = col[top + m][i];
			rc = scene_function_eval_many(s, o->arg, n, a, col[top], pattern, ctx);
			free(a);
		} else {
			int k = fops[o->op].arity;
			top -= k;
			for (int i = 0; i < n; i++) {
				double a[SCENE_FOP_ARITY_MAX];
				for (int m = 0; m < k; m++)
					a[m] = col[top + m][i];
				col[top][i] = scene_fop_apply(o->op, a);
			}
		}
		top++;
	}
	for (int i = 0; i < n && rc == 0; i++)
		out[i] = top > 0 ? col[top - 1][i] : 0;
	free(stack);
	return rc;
}

/* The levels below each function and pigment, found once each (a chain of
 * functions that call the one before twice would be walked 2^n times
 * otherwise): memo[i] -1 not yet, -2 being found (a cycle: too deep). */
struct levels {
	const scene *s;
	int *fmemo, *pmemo;
};

static int function_levels(struct levels *lv, int f);

static int pigment_levels(struct levels *lv, int pg)
{
	const scene *s = lv->s;
	if (pg < 0 || pg >= s->n_pigments)
		return 0;
	if (lv->pmemo[pg] != -1)
		return lv->pmemo[pg] == -2 ? SCENE_FUNCTION_LEVELS_MAX + 1 : lv->pmemo[pg];
	lv->pmemo[pg] = -2;
	const scene_pigment *p = &s->pigments[pg];
	int most = p->kind == PATTERN_FUNCTION ? function_levels(lv, (int)p->params[0][0]) : 0;
	for (int i = 0; i < p->n_map; i++) {
		int l = pigment_levels(lv, p->map[i].pigment);
		most = l > most ? l : most;
	}
	return lv->pmemo[pg] = most;
}

static int function_levels(struct levels *lv, int f)
{
	const scene *s = lv->s;
	if (f < 0 || f >= s->n_functions)
		return 0;
	if (lv->fmemo[f] != -1)
		return lv->fmemo[f] == -2 ? SCENE_FUNCTION_LEVELS_MAX + 1 : lv->fmemo[f];
	lv->fmemo[f] = -2;
	const scene_function *fn = &s->functions[f];
	int level = 1;
	for (int i = 0; i < fn->n_ops; i++) {
		const scene_fop *o = &fn->ops[i];
		int l = o->op == FOP_PATTERN || o->op == FOP_PIGMENT ? 1 + pigment_levels(lv, o->arg)
		      : o->op == FOP_CALL ? function_levels(lv, o->arg) : 1;
		level = l > level ? l : level;
	}
	return lv->fmemo[f] = level;
}

static int levels_of(const scene *s, int f, int pigment)
{
	struct levels lv = { s, malloc(((size_t)s->n_functions + 1) * sizeof(int)),
	                     malloc(((size_t)s->n_pigments + 1) * sizeof(int)) };
	if (!lv.fmemo || !lv.pmemo)
		abort();
	memset(lv.fmemo, 0xff, ((size_t)s->n_functions + 1) * sizeof(int));
	memset(lv.pmemo, 0xff, ((size_t)s->n_pigments + 1) * sizeof(int));
	int l = f >= 0 ? function_levels(&lv, f) : pigment_levels(&lv, pigment);
	free(lv.fmemo);
	free(lv.pmemo);
	return l;
}

int scene_function_levels(const scene *s, int f)
{
	return levels_of(s, f, -1);
}

int scene_pigment_levels(const scene *s, int pigment)
{
	return levels_of(s, -1, pigment);
}

/* Calls reach only functions made before the caller (eval compiles a callee
 * first), so the walk ends; depth guards a malformed pool all the same. */
static bool calls_patterns(const scene *s, int f, int depth)
{
	if (f < 0 || f >= s->n_functions || depth > 64)
		return false;
	const scene_function *fn = &s->functions[f];
	for (int i = 0; i < fn->n_ops; i++) {
		const scene_fop *o = &fn->ops[i];
		if (o->op == FOP_PATTERN || o->op == FOP_PIGMENT)
			return true;
		if (o->op == FOP_CALL && calls_patterns(s, o->arg, depth + 1))
			return true;
	}
	return false;
}

bool scene_function_calls_patterns(const scene *s, int f)
{
	return calls_patterns(s, f, 0);
}
