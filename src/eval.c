/* eval.c: walks the syntax tree in file order, as POV-Ray's parser does: the
 * symbol scopes, the cursor that runs the directives among a block's items
 * (#if, #while, #for, #switch, macro calls, #include), and the scene's top level.
 * Expressions are in eval_expr.c, objects in eval_object.c, textures in
 * eval_material.c, the camera, lights and global settings in eval_world.c. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "eval_int.h"
#include "mesh_io.h"
#include "parse.h"

/* ---- messages ---- */

#define MAX_NOTES 4

static bool same_context(const struct context *a, const struct context *b)
{
	return strcmp(diag_source_name(a->from.file), diag_source_name(b->from.file)) == 0 &&
	       a->from.line == b->from.line && a->from.col == b->from.col &&
	       (a->macro == b->macro || (a->macro && b->macro && strcmp(a->macro, b->macro) == 0));
}

/* The chain of includes and macro calls that led to the message, innermost
 * first; a recursion (the same call again and again) is said once. */
static void context_notes(struct eval *e)
{
	int shown = 0;
	for (int i = e->n_ctx - 1; i >= 0; shown++) {
		if (shown == MAX_NOTES) {
			diag_note(SRC_NOWHERE, "and %d more includes and macro calls", i + 1);
			return;
		}
		int j = i;
		while (j > 0 && same_context(&e->ctx[j - 1], &e->ctx[i]))
			j--;
		if (e->ctx[i].macro)
			diag_note(e->ctx[i].from, "in macro '%s' called from here", e->ctx[i].macro);
		else
			diag_note(e->ctx[i].from, "in file included from here");
		if (j < i)
			diag_note(SRC_NOWHERE, "and from the same place %d more time%s", i - j, i - j == 1 ? "" : "s");
		i = j - 1;
	}
}

static void check_error_limit(struct eval *e)
{
	if (!e->stop && diag_error_count() >= EVAL_MAX_ERRORS) {
		e->stop = true;
		diag_note(SRC_NOWHERE, "too many errors; stopped after %d", EVAL_MAX_ERRORS);
	}
}

void eval_error(struct eval *e, src_loc loc, const char *fmt, ...)
{
	char msg[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (e->stop)
		return;
	diag_error(loc, "%s", msg);
	context_notes(e);
	check_error_limit(e);
	/* The same place again: a loop or a recursion repeating its error; the
	 * rest would be copies of it. */
	src_loc *last = &e->last_error;
	if (loc.file == last->file && loc.line == last->line && loc.col == last->col && !e->stop) {
		e->stop = true;
		diag_note(SRC_NOWHERE, "stopped at the second error in the same place");
	}
	*last = loc;
}

void eval_warning(struct eval *e, src_loc loc, const char *fmt, ...)
{
	char msg[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (e->deferring) {
		e->pending = eval_xrealloc(e->pending, (e->n_pending + 1) * sizeof *e->pending);
		e->pending[e->n_pending++] = (struct eval_warning){ loc, eval_xstrdup(msg) };
		return;
	}
	diag_warning(loc, "%s", msg);
	context_notes(e);
}

void eval_warn_once(struct eval *e, src_loc loc, const char *key, const char *fmt, ...)
{
	char place[160];
	snprintf(place, sizeof place, "%d:%d:%d %s", loc.file, loc.line, loc.col, key);
	for (int i = 0; i < e->n_warned; i++)
		if (strcmp(e->warned[i], place) == 0)
			return;
	e->warned = eval_xrealloc(e->warned, (e->n_warned + 1) * sizeof *e->warned);
	e->warned[e->n_warned++] = eval_xstrdup(place);
	char msg[1024];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	eval_warning(e, loc, "%s", msg);
}

/* ---- symbols ---- */

struct symbol {
	char *name;
	value val;
	struct eval_warning *warnings;   /* waiting until the scene uses it (eval_used) */
	int n_warnings;
	struct symbol *ref;   /* a macro parameter given a declared identifier: that one */
	bool undefined;       /* #undef: kept, so that a parameter referring to it stays valid */
	struct symbol *next;
};

struct scope {
	struct symbol **bucket;
	unsigned n_bucket, count;
	struct scope *parent;
};

static unsigned hash(const char *s)
{
	unsigned h = 2166136261u;
	while (*s)
		h = (h ^ (unsigned char)*s++) * 16777619u;
	return h;
}

static struct scope *scope_new(unsigned n_bucket)
{
	struct scope *s = eval_xrealloc(NULL, sizeof *s);
	*s = (struct scope){ .n_bucket = n_bucket };
	s->bucket = eval_xrealloc(NULL, n_bucket * sizeof *s->bucket);
	memset(s->bucket, 0, n_bucket * sizeof *s->bucket);
	return s;
}

static void scope_free(struct scope *s)
{
	for (unsigned i = 0; i < s->n_bucket; i++)
		for (struct symbol *y = s->bucket[i], *next; y; y = next) {
			next = y->next;
			eval_value_free(&y->val);
			for (int k = 0; k < y->n_warnings; k++)
				free(y->warnings[k].msg);
			free(y->warnings);
			free(y->name);
			free(y);
		}
	free(s->bucket);
	free(s);
}

static void scope_grow(struct scope *s)
{
	unsigned n = s->n_bucket * 4;
	struct symbol **b = calloc(n, sizeof *b);
	if (!b)
		return;  /* longer chains, still correct */
	for (unsigned i = 0; i < s->n_bucket; i++)
		for (struct symbol *y = s->bucket[i], *next; y; y = next) {
			next = y->next;
			y->next = b[hash(y->name) % n];
			b[hash(y->name) % n] = y;
		}
	free(s->bucket);
	s->bucket = b;
	s->n_bucket = n;
}

static struct symbol *scope_find(const struct scope *s, const char *name)
{
	for (struct symbol *y = s->bucket[hash(name) % s->n_bucket]; y; y = y->next)
		if (strcmp(y->name, name) == 0)
			return y;
	return NULL;
}

static struct symbol *scope_add(struct scope *s, const char *name)
{
	if (s->count >= 2 * s->n_bucket)
		scope_grow(s);
	struct symbol *y = eval_xrealloc(NULL, sizeof *y);
	*y = (struct symbol){ .name = eval_xstrdup(name), .undefined = true };
	unsigned h = hash(name) % s->n_bucket;
	y->next = s->bucket[h];
	s->bucket[h] = y;
	s->count++;
	return y;
}

static struct symbol *resolve(struct symbol *y)
{
	while (y->ref)
		y = y->ref;
	return y;
}

/* The visible symbol of that name, followed through parameter references. */
static struct symbol *visible(struct eval *e, const char *name)
{
	for (struct scope *s = e->scope; s; s = s->parent) {
		struct symbol *y = scope_find(s, name);
		if (y && !y->undefined)
			return resolve(y)->undefined ? NULL : resolve(y);
	}
	return NULL;
}

void eval_used(struct eval *e, const char *name, src_loc loc)
{
	struct symbol *y = visible(e, name);
	if (!y || y->n_warnings == 0)
		return;
	struct eval_warning *w = y->warnings;
	int n = y->n_warnings;
	y->warnings = NULL;
	y->n_warnings = 0;
	for (int i = 0; i < n; i++) {
		eval_warning(e, w[i].loc, "%s", w[i].msg);
		if (!e->deferring)
			diag_note(loc, "where '%s' is used", name);
		free(w[i].msg);
	}
	free(w);
}

/* The warnings that waited while a declaration was evaluated go to its symbol. */
static void keep_warnings(struct eval *e, const char *name, int from)
{
	struct symbol *y = e->n_pending > from ? visible(e, name) : NULL;
	for (int i = from; i < e->n_pending; i++) {
		if (y) {
			y->warnings = eval_xrealloc(y->warnings, (y->n_warnings + 1) * sizeof *y->warnings);
			y->warnings[y->n_warnings++] = e->pending[i];
		} else {
			free(e->pending[i].msg);
		}
	}
	e->n_pending = from;
}

value *eval_lookup(struct eval *e, const char *name)
{
	struct symbol *y = visible(e, name);
	return y ? &y->val : NULL;
}

static void set_symbol(struct symbol *y, value v)
{
	y = resolve(y);
	eval_value_free(&y->val);
	y->val = v;
	y->undefined = false;
}

/* POV-Ray's rules: #declare changes the visible identifier of that name, whatever
 * scope it is in, else makes a global one; #local changes the one in the
 * innermost scope (the macro or the include file), else makes one there. */
void eval_assign(struct eval *e, const char *name, value v, bool local)
{
	struct symbol *y = local ? scope_find(e->scope, name) : visible(e, name);
	if (!y)
		y = local ? scope_add(e->scope, name)
		          : (y = scope_find(e->global, name)) ? y : scope_add(e->global, name);
	set_symbol(y, v);
}

bool eval_undef(struct eval *e, const char *name)
{
	for (struct scope *s = e->scope; s; s = s->parent) {
		struct symbol *y = scope_find(s, name);
		if (y && !y->undefined) {
			y = resolve(y);
			eval_value_free(&y->val);
			y->val = (value){ .kind = V_NONE };
			y->undefined = true;
			return true;
		}
	}
	return false;
}

static void scope_push(struct eval *e, struct scope *s)
{
	s->parent = e->scope;
	e->scope = s;
}

static void scope_pop(struct eval *e)
{
	struct scope *s = e->scope;
	e->scope = s->parent;
	scope_free(s);
}

/* Edit distance with adjacent transpositions (Damerau-Levenshtein, optimal
 * string alignment), for "did you mean": "Rign" is 1 from "Ring". */
static int distance(const char *a, const char *b)
{
	int la = (int)strlen(a), lb = (int)strlen(b);
	if (la > 64 || lb > 64)
		return 99;
	int d[65][65];
	for (int i = 0; i <= la; i++)
		d[i][0] = i;
	for (int j = 0; j <= lb; j++)
		d[0][j] = j;
	for (int i = 1; i <= la; i++)
		for (int j = 1; j <= lb; j++) {
			int best = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
			if (d[i - 1][j] + 1 < best)
				best = d[i - 1][j] + 1;
			if (d[i][j - 1] + 1 < best)
				best = d[i][j - 1] + 1;
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < best)
				best = d[i - 2][j - 2] + 1;
			d[i][j] = best;
		}
	return d[la][lb];
}

/* The declared name closest to name, if close enough to be a typo; "" if none. */
void eval_suggest(struct eval *e, const char *name, char *out, size_t size)
{
	size_t len = strlen(name);
	int best = (len <= 2 ? 0 : len <= 5 ? 1 : len <= 9 ? 2 : 3) + 1;
	out[0] = '\0';
	for (struct scope *s = e->scope; s; s = s->parent)
		for (unsigned i = 0; i < s->n_bucket; i++)
			for (struct symbol *y = s->bucket[i]; y; y = y->next) {
				if (y->undefined)
					continue;
				int d = distance(name, y->name);
				if (d < best || (d == best && strcmp(y->name, out) < 0)) {
					best = d;
					snprintf(out, size, "%s", y->name);
				}
			}
}

/* ---- the cursor ---- */

enum frame_kind { FR_LIST, FR_WHILE, FR_FOR, FR_SWITCH, FR_MACRO, FR_INCLUDE };

struct frame {
	enum frame_kind kind;
	const ast_node *list;    /* its kids are the items */
	int i;                   /* the next one */
	const ast_node *node;    /* #while, #for */
	long count;              /* loop iterations */
	double end, step;        /* #for */
	bool scope, ctx;         /* pushed a scope, a context entry, to pop at the end */
};

void eval_cursor_init(struct cursor *c, struct eval *e, const ast_node *block)
{
	*c = (struct cursor){ .e = e };
	if (block) {
		c->frames = eval_xrealloc(NULL, 4 * sizeof *c->frames);
		c->cap = 4;
		c->frames[c->n++] = (struct frame){ .kind = FR_LIST, .list = block };
	}
}

static struct frame *push_frame(struct cursor *c, enum frame_kind kind, const ast_node *list)
{
	if (c->n == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 4;
		c->frames = eval_xrealloc(c->frames, c->cap * sizeof *c->frames);
	}
	struct frame *f = &c->frames[c->n++];
	*f = (struct frame){ .kind = kind, .list = list };
	return f;
}

static void pop_frame(struct cursor *c)
{
	struct eval *e = c->e;
	struct frame *f = &c->frames[--c->n];
	if (f->scope)
		scope_pop(e);
	if (f->ctx)
		e->n_ctx--;
	if (f->kind == FR_MACRO)
		e->macro_depth--;
	if (f->kind == FR_INCLUDE)
		e->include_depth--;
}

void eval_cursor_free(struct cursor *c)
{
	while (c->n > 0)
		pop_frame(c);
	free(c->frames);
	c->frames = NULL;
}

void eval_unget(struct cursor *c, const ast_node *item)
{
	c->pending = item;
}

static void push_context(struct eval *e, struct frame *f, const char *macro, src_loc from)
{
	if (e->n_ctx < EVAL_MAX_CONTEXT) {
		e->ctx[e->n_ctx++] = (struct context){ macro, from };
		f->ctx = true;
	}
}

/* ---- conditions and loops ---- */

bool eval_truth(double f)
{
	return fabs(f) > 1e-10;   /* POV-Ray's EPSILON */
}

/* (Cond) of #if, #while, #elseif: a float; -1 on error. */
static int condition(struct eval *e, const ast_node *n)
{
	double f;
	if (eval_expect_float(e, n, &f))
		return -1;
	return eval_truth(f);
}

static bool loop_limit(struct eval *e, struct frame *f)
{
	long max = e->opt->max_loop_iterations > 0 ? e->opt->max_loop_iterations : EVAL_DEFAULT_LOOP_ITERATIONS;
	if (++f->count < max)
		return false;
	eval_error(e, f->node->loc, "#%s loop stopped after %ld iterations (a loop that never ends? "
	           "--max-loop-iterations raises the limit)", f->kind == FR_WHILE ? "while" : "for", max);
	return true;
}

/* POV-Ray's test, with its EPSILON: #for (I, 0, 0.3, 0.1) runs 4 times although
 * 0.1 + 0.1 + 0.1 is a little more than 0.3. */
static bool for_continues(double v, double end, double step)
{
	return step > 0 ? v <= end + 1e-10 : v >= end - 1e-10;
}

/* The end of a loop's body: run it again or leave. */
static void loop_again(struct cursor *c)
{
	struct eval *e = c->e;
	struct frame *f = &c->frames[c->n - 1];
	if (loop_limit(e, f)) {
		pop_frame(c);
		return;
	}
	if (f->kind == FR_WHILE) {
		if (condition(e, f->node->kids[0]) == 1) {
			f->i = 0;
			return;
		}
		pop_frame(c);
		return;
	}
	value *var = eval_lookup(e, f->node->str);
	if (!var || var->kind != V_FLOAT) {
		eval_error(e, f->node->loc, "the #for variable '%s' is no longer a float", f->node->str);
		pop_frame(c);
		return;
	}
	double next = var->v[0] + f->step;
	eval_assign(e, f->node->str, eval_float(next), true);
	if (for_continues(next, f->end, f->step))
		f->i = 0;
	else
		pop_frame(c);
}

/* #while (Cond) ... #end */
static void run_while(struct cursor *c, const ast_node *d)
{
	if (condition(c->e, d->kids[0]) != 1)
		return;
	struct frame *f = push_frame(c, FR_WHILE, d->kids[1]);
	f->node = d;
}

/* #for (Identifier, Start, End [, Step]) ... #end: Identifier goes from Start
 * while it is not past End, adding Step (default 1) after each pass. */
static void run_for(struct cursor *c, const ast_node *d)
{
	struct eval *e = c->e;
	double start, end, step = 1;
	int has_step = d->n_kids == 4;
	if (eval_expect_float(e, d->kids[0], &start) || eval_expect_float(e, d->kids[1], &end) ||
	    (has_step && eval_expect_float(e, d->kids[2], &step)))
		return;
	if (step == 0) {
		eval_error(e, d->kids[2]->loc, "#for with a step of 0 never ends");
		return;
	}
	eval_assign(e, d->str, eval_float(start), true);
	if (!for_continues(start, end, step))
		return;
	struct frame *f = push_frame(c, FR_FOR, d->kids[d->n_kids - 1]);
	f->node = d;
	f->end = end;
	f->step = step;
}

/* #if (Cond) ... [#elseif (Cond) ...]... [#else ...] #end, and #ifdef, #ifndef. */
static void run_if(struct cursor *c, const ast_node *d)
{
	struct eval *e = c->e;
	int i = 0;
	for (; i + 1 < d->n_kids; i += 2) {
		int truth;
		if (i == 0 && d->op != 'i')
			truth = eval_is_defined(e, d->kids[0]) == (d->op == 'd');
		else
			truth = condition(e, d->kids[i]);
		if (truth < 0)
			return;
		if (truth) {
			push_frame(c, FR_LIST, d->kids[i + 1]);
			return;
		}
	}
	if (i < d->n_kids)
		push_frame(c, FR_LIST, d->kids[i]);
}

/* #switch (Value) [#case (V) | #range (Low, High) ... [#break]]... [#else ...] #end:
 * the items after the first clause that matches, through the clauses after it,
 * up to a #break. */
static void run_switch(struct cursor *c, const ast_node *d)
{
	struct eval *e = c->e;
	double v, a, b;
	if (eval_expect_float(e, d->kids[0], &v))
		return;
	const ast_node *body = d->kids[1];
	for (int i = 0; i < body->n_kids; i++) {
		const ast_node *k = body->kids[i];
		int match = 0;
		if (k->kind == AST_CASE) {
			if (eval_expect_float(e, k->kids[0], &a))
				return;
			match = !eval_truth(v - a);
		} else if (k->kind == AST_RANGE) {
			if (eval_expect_float(e, k->kids[0], &a) || eval_expect_float(e, k->kids[1], &b))
				return;
			match = v >= a && v <= b;
		} else {
			match = k->kind == AST_ELSE;
		}
		if (match) {
			push_frame(c, FR_SWITCH, body)->i = i + 1;
			return;
		}
	}
}

/* #break: leaves the innermost #switch, loop or macro. */
static void run_break(struct cursor *c, const ast_node *d)
{
	while (c->n > 0) {
		enum frame_kind k = c->frames[c->n - 1].kind;
		if (k == FR_INCLUDE)
			break;
		pop_frame(c);
		if (k == FR_SWITCH || k == FR_WHILE || k == FR_FOR || k == FR_MACRO)
			return;
		if (c->n == 0)
			break;
	}
	eval_error(c->e, d->loc, "#break outside #switch, #while, #for and #macro");
}

/* ---- macros ---- */

/* #macro Name ([Param, ...]) ... #end: macros are global, as in POV-Ray. */
static void define_macro(struct eval *e, const ast_node *d)
{
	struct symbol *y = scope_find(e->global, d->str);
	if (!y)
		y = scope_add(e->global, d->str);
	set_symbol(y, (value){ .kind = V_MACRO, .node = d });
}

/* Binds the arguments of a call in a new scope. An argument that is a declared
 * identifier is passed by reference: the macro's #declare or #local of the
 * parameter changes it, as in POV-Ray. */
static struct scope *bind_args(struct eval *e, const ast_node *call, const ast_node *def)
{
	const ast_node *params = def->kids[0];
	if (call->n_kids != params->n_kids) {
		eval_error(e, call->loc, "macro '%s' takes %d argument%s, not %d", call->str, params->n_kids,
		           params->n_kids == 1 ? "" : "s", call->n_kids);
		return NULL;
	}
	struct scope *s = scope_new(16);
	for (int i = 0; i < call->n_kids; i++) {
		const ast_node *arg = call->kids[i];
		struct symbol *target = arg->kind == AST_IDENT ? visible(e, arg->str) : NULL;
		value v = { .kind = V_NONE };
		int rc = target ? 0 : AST_IS_EXPRESSION(arg->kind) ? eval_expr(e, arg, &v) : eval_block_value(e, arg, &v);
		if (rc) {
			scope_free(s);
			return NULL;
		}
		struct symbol *y = scope_find(s, params->kids[i]->str);
		if (!y)
			y = scope_add(s, params->kids[i]->str);
		if (target) {
			y->ref = target;
			y->undefined = false;
		} else {
			set_symbol(y, v);
		}
	}
	return s;
}

static bool enter_macro(struct cursor *c, const ast_node *call, const value *macro)
{
	struct eval *e = c->e;
	int max = e->opt->max_macro_depth > 0 ? e->opt->max_macro_depth : EVAL_DEFAULT_MACRO_DEPTH;
	if (e->macro_depth >= max) {
		eval_error(e, call->loc, "macro '%s' called more than %d levels deep (a recursion that never ends? "
		           "--max-macro-depth raises the limit)", call->str, max);
		return false;
	}
	const ast_node *def = macro->node;   /* the arguments may redeclare the macro */
	const ast_node *body = def->kids[1];
	if (body->kind == AST_MESSAGE) {   /* its syntax error, kept until now (parse_macro_body) */
		bool pushed = e->n_ctx < EVAL_MAX_CONTEXT;
		if (pushed)
			e->ctx[e->n_ctx++] = (struct context){ def->str, call->loc };
		eval_error(e, body->loc, "%s", body->str);
		e->n_ctx -= pushed;
		return false;
	}
	struct scope *s = bind_args(e, call, def);
	if (!s)
		return false;
	scope_push(e, s);
	e->macro_depth++;
	struct frame *f = push_frame(c, FR_MACRO, body);
	f->scope = true;
	push_context(e, f, def->str, call->loc);
	return true;
}

/* The names n's subtree uses (identifiers, and calls of functions) that are
 * visible here but not global, into env with a copy of their values. */
static void capture_names(struct eval *e, const ast_node *n, struct scope **env)
{
	if ((n->kind == AST_IDENT || n->kind == AST_CALL) && n->str && (!*env || !scope_find(*env, n->str))) {
		struct symbol *y = visible(e, n->str);
		struct symbol *g = scope_find(e->global, n->str);
		if (y && (!g || resolve(g) != y)) {
			if (!*env)
				*env = scope_new(8);
			set_symbol(scope_add(*env, n->str), eval_value_copy(&y->val));
		}
	}
	for (int i = 0; i < n->n_kids; i++)
		if (n->kids[i])
			capture_names(e, n->kids[i], env);
}

struct scope *eval_capture(struct eval *e, const ast_node *def)
{
	if (e->scope == e->global || def->n_kids < 2)
		return NULL;
	struct scope *env = NULL;
	capture_names(e, def->kids[1], &env);
	if (env) {
		e->envs = eval_xrealloc(e->envs, (e->n_envs + 1) * sizeof *e->envs);
		e->envs[e->n_envs++] = env;
	}
	return env;
}

/* Not when env is in sight already (a function calling itself, which its
 * depth limit stops): pushing it twice would make a loop of scopes. */
int eval_env_push(struct eval *e, struct scope *env)
{
	if (!env)
		return 0;
	for (struct scope *s = e->scope; s; s = s->parent)
		if (s == env)
			return 0;
	scope_push(e, env);
	return 1;
}

void eval_env_pop(struct eval *e, int pushed)
{
	if (pushed)
		e->scope = e->scope->parent;   /* env stays, for the function's next use */
}

int eval_function_body(struct eval *e, const ast_node *def, const char *const *names, const double *args, int n,
                       value *out)
{
	struct scope *s = scope_new(8);
	for (int i = 0; i < n; i++) {
		const char *name = names ? names[i] : def->kids[0]->kids[i]->str;
		struct symbol *y = scope_find(s, name);
		set_symbol(y ? y : scope_add(s, name), eval_float(args[i]));
	}
	scope_push(e, s);
	int rc = eval_expr(e, def->kids[1]->kids[0], out);
	scope_pop(e);
	if (rc == 0 && out->kind != V_FLOAT) {
		eval_error(e, def->kids[1]->kids[0]->loc, "a function must give a float, this one gives %s",
		           eval_kind_name(out->kind));
		eval_value_free(out);
		return -1;
	}
	return rc;
}

static const value *macro_called(struct eval *e, const ast_node *item)
{
	if (item->kind != AST_CALL)
		return NULL;
	const value *v = eval_lookup(e, item->str);
	return v && v->kind == V_MACRO ? v : NULL;
}

/* The one value the items of a cursor give, after the directives among them:
 * a macro's body in a value position, a branch of (#if ...). */
static int one_value(struct eval *e, struct cursor *c, src_loc loc, const char *what, value *out)
{
	int err = 0, rc = -1;
	const ast_node *item = eval_next(c, &err);
	if (!item) {
		if (!err)
			eval_error(e, loc, "%s gives no value", what);
	} else if (AST_IS_EXPRESSION(item->kind)) {
		rc = eval_expr(e, item, out);
	} else {
		rc = eval_block_value(e, item, out);
	}
	const ast_node *more = rc == 0 ? eval_next(c, &err) : NULL;
	if (more) {
		eval_error(e, more->loc, "%s gives more than one value where one is expected", what);
		eval_value_free(out);
		rc = -1;
	} else if (err && rc == 0) {
		eval_value_free(out);
		rc = -1;
	}
	eval_cursor_free(c);
	return rc;
}

int eval_macro_value(struct eval *e, const ast_node *call, const value *macro, value *out)
{
	struct cursor c;
	char what[300];
	eval_cursor_init(&c, e, NULL);
	if (!enter_macro(&c, call, macro)) {
		eval_cursor_free(&c);
		return -1;
	}
	snprintf(what, sizeof what, "macro '%s'", call->str);
	return one_value(e, &c, call->loc, what, out);
}

/* (#if (Cond) ITEMS [#elseif (Cond) ITEMS]... [#else ITEMS] #end) */
int eval_if_value(struct eval *e, const ast_node *n, value *out)
{
	struct cursor c;
	eval_cursor_init(&c, e, NULL);
	run_if(&c, n);
	if (c.n == 0) {
		eval_cursor_free(&c);
		eval_error(e, n->loc, "this #if gives no value: no branch was taken");
		return -1;
	}
	return one_value(e, &c, n->loc, "this #if", out);
}

/* ---- #include ---- */

static bool readable(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0 && S_ISREG(st.st_mode) && access(path, R_OK) == 0;
}

static char *join(const char *dir, size_t n, const char *name)
{
	char *p = NULL;
	if (asprintf(&p, "%.*s/%s", (int)n, dir, name) < 0)
		eval_xrealloc(NULL, (size_t)-1 / 2);
	return p;
}

static char *try_dir(const char *dir, size_t n, const char *name)
{
	char *p = join(dir, n, name);
	if (readable(p))
		return p;
	free(p);
	return NULL;
}

/* A colon-separated list of folders. */
static char *try_path(const char *list, const char *name)
{
	while (list && *list) {
		size_t n = strcspn(list, ":");
		char *p = n ? try_dir(list, n, name) : NULL;
		if (p)
			return p;
		list += n + (list[n] == ':');
	}
	return NULL;
}

/* Where a file named in the scene is: next to the file that names it, then in
 * the -I folders, $ECLAT_INCLUDE_PATH, eclat's installed include folder,
 * POV-Ray's include folder. NULL if none;
 * *first is then the name relative to the file that names it. */
static char *find_file(struct eval *e, int from_file, const char *name, char **first)
{
	const char *from = diag_source_name(from_file);
	const char *slash = from_file >= 0 ? strrchr(from, '/') : NULL;
	*first = name[0] == '/' || !slash ? eval_xstrdup(name) : join(from, slash - from, name);
	if (readable(*first) || name[0] == '/')
		return readable(*first) ? eval_xstrdup(*first) : NULL;
	char *p = NULL;
	for (int i = 0; !p && e->opt && i < e->opt->n_include_dirs; i++)
		p = try_dir(e->opt->include_dirs[i], strlen(e->opt->include_dirs[i]), name);
	if (!p)
		p = try_path(getenv("ECLAT_INCLUDE_PATH"), name);
	if (!p && eval_installed_include_dir())
		p = try_dir(eval_installed_include_dir(), strlen(eval_installed_include_dir()), name);
	if (!p)
		p = try_dir(EVAL_POV_INCLUDE_DIR, strlen(EVAL_POV_INCLUDE_DIR), name);
	return p;
}

/* A file the scene may not read is one it cannot tell is there. */
bool eval_file_exists(struct eval *e, int from_file, const char *name)
{
	char *first, *p = find_file(e, from_file, name, &first);
	bool there = p && eval_access_allowed(e, p, false);
	free(first);
	free(p);
	return there;
}

char *eval_find_file(struct eval *e, int from_file, const char *name)
{
	char *first, *p = find_file(e, from_file, name, &first);
	free(first);
	return p;
}

static void keep_tree(struct eval *e, ast_node *tree)
{
	e->trees = eval_xrealloc(e->trees, (e->n_trees + 1) * sizeof *e->trees);
	e->trees[e->n_trees++] = tree;
}

/* #include "File": its items run here, in a scope of its own for #local. */
static void run_include(struct cursor *c, const ast_node *inc)
{
	struct eval *e = c->e;
	char *name;
	if (eval_expect_string(e, inc->kids[0], &name))
		return;
	int max = e->opt->max_include_depth > 0 ? e->opt->max_include_depth : EVAL_DEFAULT_INCLUDE_DEPTH;
	if (e->include_depth >= max) {
		eval_error(e, inc->loc, "#include nested more than %d deep (an include cycle? "
		           "--max-include-depth raises the limit)", max);
		free(name);
		return;
	}
	char *first, *path = find_file(e, inc->loc.file, name, &first);
	free(name);
	int refused = eval_access(e, path ? path : first, false, inc->loc, "#include");
	ast_node *tree = refused ? NULL : parse_file(path ? path : first, inc->kids[0]->loc);
	free(path);
	free(first);
	if (refused)
		return;
	if (!tree) {
		context_notes(e);
		check_error_limit(e);
		return;
	}
	keep_tree(e, tree);
	struct frame *f = push_frame(c, FR_INCLUDE, tree);
	scope_push(e, scope_new(64));
	f->scope = true;
	e->include_depth++;
	push_context(e, f, NULL, inc->loc);
}

/* #declare V = #include "File": the one value the file gives, as POV-Ray reads
 * it (its mesh camera demos keep a mesh in a file this way). */
static int include_value(struct eval *e, const ast_node *inc, value *out)
{
	struct cursor c;
	int errors = diag_error_count();
	eval_cursor_init(&c, e, NULL);
	run_include(&c, inc);
	if (c.n == 0 || diag_error_count() > errors) {
		eval_cursor_free(&c);
		return -1;
	}
	return one_value(e, &c, inc->loc, "this #include", out);
}

/* ---- the other directives ---- */

static int array_target(struct eval *e, const ast_node *d, value v);

/* #declare NAME [Index...] = VALUE, #local ... */
/* POV-Ray 3.5 and later want a ';' after a #declare of a float, a vector or
 * a colour (its Parse_Semi_Colon). A macro's call may bring its own ';'
 * (eclat does not expand macros into tokens), so it is let through. */
static void check_semicolon(struct eval *e, const ast_node *d, const value *v)
{
	const ast_node *rhs = d->kids[0];
	if (d->num != 0 || e->version < 3.5 || (v->kind != V_FLOAT && v->kind != V_VECTOR && v->kind != V_COLOR))
		return;
	if (rhs->kind == AST_CALL) {
		const value *callee = eval_lookup(e, rhs->str);
		if (callee && callee->kind == V_MACRO)
			return;
	}
	eval_error(e, d->loc, "a #%s of a float, vector or colour needs a ';' after its value under #version 3.5 "
	           "and later, as in POV-Ray (add it, or say #version 3.1)", d->op == 'l' ? "local" : "declare");
}

static void run_declare(struct eval *e, const ast_node *d)
{
	const ast_node *rhs = d->kids[0];
	value v;
	/* an include file's declarations warn when the scene uses them */
	bool defer = e->include_depth > 0 && d->n_kids == 1;
	int from = e->n_pending;
	e->deferring += defer;
	int rc = AST_IS_EXPRESSION(rhs->kind) ? eval_expr(e, rhs, &v) :
	         rhs->kind == AST_INCLUDE ? include_value(e, rhs, &v) : eval_block_value(e, rhs, &v);
	e->deferring -= defer;
	if (rc == 0)   /* an error, but X is declared all the same: no "undeclared X" after it */
		check_semicolon(e, d, &v);
	if (rc == 0 && d->n_kids > 1)
		array_target(e, d, v);
	else if (rc == 0)
		eval_assign(e, d->str, v, d->op == 'l');
	if (defer)
		keep_warnings(e, rc == 0 ? d->str : "", from);
}

/* #declare A[I][J] = V: the element must exist. */
static int array_target(struct eval *e, const ast_node *d, value v)
{
	value *a = eval_lookup(e, d->str);
	if (!a || a->kind != V_ARRAY) {
		eval_error(e, d->loc, a ? "'%s' is not an array" : "undeclared array '%s'", d->str);
		eval_value_free(&v);
		return -1;
	}
	int n = d->n_kids - 1, at = 0;
	if (n != a->arr->dims) {
		eval_error(e, d->kids[1]->loc, "'%s' has %d dimensions, not %d", d->str, a->arr->dims, n);
		eval_value_free(&v);
		return -1;
	}
	for (int k = 0; k < n; k++) {
		int i;
		if (eval_expect_int(e, d->kids[k + 1], &i) || i < 0 || i >= a->arr->size[k]) {
			if (i < 0 || i >= a->arr->size[k])
				eval_error(e, d->kids[k + 1]->loc, "index %d is out of the range 0 to %d of '%s'", i,
				           a->arr->size[k] - 1, d->str);
			eval_value_free(&v);
			return -1;
		}
		at = at * a->arr->size[k] + i;
	}
	a = eval_lookup(e, d->str);  /* the index may have run a macro that changed it */
	if (!a || a->kind != V_ARRAY || at >= a->arr->n) {
		eval_value_free(&v);
		return -1;
	}
	eval_value_free(&a->arr->elems[at]);
	a->arr->elems[at] = v;
	return 0;
}

/* #debug, #warning, #error "Text" */
static void run_message(struct eval *e, const ast_node *d)
{
	char *text;
	if (eval_expect_string(e, d->kids[0], &text))
		return;
	if (d->op == 'd') {
		fputs(text, stderr);
	} else if (d->op == 'w') {
		eval_warning(e, d->loc, "%s", text);
	} else {
		eval_error(e, d->loc, "#error: %s", text);
		e->stop = true;
	}
	free(text);
}

/* #version V[;]: sets the value of version. */
static void run_version(struct eval *e, const ast_node *d)
{
	double v;
	if (eval_expect_float(e, d->kids[0], &v))
		return;
	e->version = v;
	e->version_given = true;
	e->version_loc = d->loc;
	struct symbol *y = scope_find(e->global, "version");
	if (!y)
		y = scope_add(e->global, "version");
	set_symbol(y, eval_float(v));
}

static void run_directive(struct cursor *c, const ast_node *d)
{
	struct eval *e = c->e;
	switch (d->kind) {
	case AST_DECLARE: run_declare(e, d); break;
	case AST_INCLUDE: run_include(c, d); break;
	case AST_MACRO: define_macro(e, d); break;
	case AST_IF: run_if(c, d); break;
	case AST_WHILE: run_while(c, d); break;
	case AST_FOR: run_for(c, d); break;
	case AST_SWITCH: run_switch(c, d); break;
	case AST_BREAK: run_break(c, d); break;
	case AST_UNDEF: eval_undef(e, d->str); break;
	case AST_VERSION: run_version(e, d); break;
	case AST_DEFAULT: eval_default(e, d); break;
	case AST_MESSAGE: run_message(e, d); break;
	case AST_CASE: case AST_RANGE: case AST_ELSE:
		break;  /* a #switch running on through the next clause */
	case AST_FILE_IO: eval_file_io(e, d); break;
	default:
		eval_error(e, d->loc, "unexpected directive");
		break;
	}
}

static bool is_directive(const ast_node *n)
{
	return n->kind >= AST_DECLARE;
}

const ast_node *eval_next(struct cursor *c, int *err)
{
	struct eval *e = c->e;
	if (c->pending) {
		const ast_node *n = c->pending;
		c->pending = NULL;
		return n;
	}
	while (c->n > 0 && !e->stop) {
		struct frame *f = &c->frames[c->n - 1];
		if (f->i >= f->list->n_kids) {
			if (f->kind == FR_WHILE || f->kind == FR_FOR)
				loop_again(c);
			else
				pop_frame(c);
			continue;
		}
		const ast_node *item = f->list->kids[f->i++];
		const value *m;
		int errors = diag_error_count();
		if (is_directive(item))
			run_directive(c, item);
		else if ((m = macro_called(e, item)) != NULL)
			enter_macro(c, item, m);
		else
			return item;
		/* In a block, an error in a directive or a call ends the block, quietly:
		 * what follows would only report its consequences. */
		if (!c->lenient && diag_error_count() > errors) {
			*err = 1;
			return NULL;
		}
	}
	if (e->stop)
		*err = 1;
	return NULL;
}

const ast_node *eval_next_expr(struct cursor *c, int *err)
{
	const ast_node *n = eval_next(c, err);
	if (n && !AST_IS_EXPRESSION(n->kind)) {
		eval_unget(c, n);
		return NULL;
	}
	return n;
}

const ast_node *eval_next_optional(struct cursor *c, int *err)
{
	const ast_node *n = eval_next_expr(c, err);
	if (n && n->kind == AST_IDENT && !eval_lookup(c->e, n->str)) {
		eval_unget(c, n);
		return NULL;
	}
	return n;
}

/* ---- the scene ---- */

static void declare_vector(struct eval *e, const char *name, int n, double a, double b, double c, double d)
{
	eval_assign(e, name, (value){ .kind = V_VECTOR, .n = n, .v = { a, b, c, d } }, false);
}

static void declare_float(struct eval *e, const char *name, double f)
{
	eval_assign(e, name, eval_float(f), false);
}

/* POV-Ray's predeclared identifiers (its reserved words x, pi, clock...), and
 * eclat_version so that a scene can test for eclat with #ifdef. */
static void declare_builtins(struct eval *e)
{
	const eval_options *o = e->opt;
	declare_vector(e, "x", 3, 1, 0, 0, 0);
	declare_vector(e, "y", 3, 0, 1, 0, 0);
	declare_vector(e, "z", 3, 0, 0, 1, 0);
	declare_vector(e, "t", 4, 0, 0, 0, 1);
	declare_vector(e, "u", 2, 1, 0, 0, 0);
	declare_vector(e, "v", 2, 0, 1, 0, 0);
	declare_float(e, "pi", M_PI);
	static const char *const yes[] = { "true", "yes", "on" }, *const no[] = { "false", "no", "off" };
	for (int i = 0; i < 3; i++) {
		declare_float(e, yes[i], 1);
		declare_float(e, no[i], 0);
	}
	declare_float(e, "clock", o->clock);
	declare_float(e, "clock_delta", o->clock_delta);
	declare_float(e, "clock_on", o->clock_on);
	declare_float(e, "frame_number", (double)o->frame_number);
	declare_float(e, "initial_clock", o->initial_clock);
	declare_float(e, "final_clock", o->final_clock);
	declare_float(e, "initial_frame", (double)o->initial_frame);
	declare_float(e, "final_frame", (double)o->final_frame);
	declare_float(e, "image_width", o->image_width > 0 ? o->image_width : 640);
	declare_float(e, "image_height", o->image_height > 0 ? o->image_height : 480);
	declare_float(e, "version", e->version);
	declare_float(e, "eclat_version", strtod(PACKAGE_VERSION, NULL));
}

/* -D NAME=VALUE: "#declare NAME = VALUE;" read from a text of its own, so that
 * an error in VALUE points into that text. */
static int declare_option(struct eval *e, const char *decl)
{
	size_t n = strcspn(decl, "=");
	if (!decl[n] || n == 0) {
		diag_error(SRC_NOWHERE, "a declaration needs the form NAME=VALUE, not '%s'", decl);
		return -1;
	}
	char *text = NULL;
	if (asprintf(&text, "#declare %.*s = %s;\n", (int)n, decl, decl + n + 1) < 0)
		eval_xrealloc(NULL, (size_t)-1 / 2);
	char name[80];
	snprintf(name, sizeof name, "<declaration %.*s>", (int)(n < 40 ? n : 40), decl);
	ast_node *tree = parse_text(name, text, strlen(text));
	if (!tree)
		return -1;
	keep_tree(e, tree);
	struct cursor c;
	int err = 0;
	eval_cursor_init(&c, e, tree);
	c.lenient = true;
	const ast_node *item = eval_next(&c, &err);
	if (item)
		eval_error(e, item->loc, "a declaration must be NAME=VALUE");
	eval_cursor_free(&c);
	return 0;
}

eval_options eval_options_default(void)
{
	return (eval_options){ .image_width = 640, .image_height = 480,
	                       .mesh_time_limit = MESH_IO_DEFAULT_TIME_LIMIT };
}

static void eval_free(struct eval *e)
{
	eval_files_close(e);
	eval_access_free(e);
	eval_outline_free(e);
	while (e->scope)
		scope_pop(e);
	for (int i = 0; i < e->n_trees; i++)
		ast_free(e->trees[i]);
	free(e->trees);
	for (int i = 0; i < e->n_warned; i++)
		free(e->warned[i]);
	free(e->warned);
	for (int i = 0; i < e->n_pending; i++)
		free(e->pending[i].msg);
	free(e->pending);
	free(e->rng.state);
	for (int i = 0; i < e->n_envs; i++)
		scope_free(e->envs[i]);
	free(e->envs);
}

/* POV-Ray 3.7's working gamma: assumed_gamma; without it, 1 when the version
 * in effect at the end of the scene is 3.7 or later, and gamma correction off
 * for an older one. A scene without #version is eclat's own and 3.7's
 * (POV-Ray turns gamma correction off for it too, with a warning:
 * eclat-scene(5) says why eclat does not). */
double eval_working_gamma(const struct eval *e)
{
	const scene *s = e->s;
	if (s->assumed_gamma > 0)
		return s->assumed_gamma;
	return e->version_given && e->version < 3.7 ? 0 : 1;
}

static void film_gamma(struct eval *e)
{
	scene *s = e->s;
	s->film_gamma = (float)eval_working_gamma(e);
	if (s->film_gamma == 0) {
		eval_warning(e, e->version_loc, "no assumed_gamma in a #version %g scene: gamma correction is off, "
		             "as in POV-Ray 3.7 (colours go into 8-bit images as they are)", e->version);
	}
}

int eval_scene(const ast_node *root, scene *s, const eval_options *opt)
{
	eval_options defaults = eval_options_default();
	struct eval e = { .s = s, .opt = opt ? opt : &defaults, .version = 3.7,
	                  .default_mat = scene_default_material(), .errors_at_start = diag_error_count() };
	eval_access_init(&e, root->loc.file);
	e.global = scope_new(256);
	scope_push(&e, e.global);
	declare_builtins(&e);
	for (int i = 0; i < e.opt->n_declares; i++)
		declare_option(&e, e.opt->declares[i]);

	struct cursor c;
	int err = 0;
	eval_cursor_init(&c, &e, root);
	c.lenient = true;
	const ast_node *item;
	while ((item = eval_next(&c, &err)) != NULL)
		eval_scene_statement(&e, item);
	eval_cursor_free(&c);
	film_gamma(&e);
	s->sky_legacy = e.version_given && e.version < 3.7;
	if (!e.noise_given)   /* POV-Ray's default, 2, is 1 for a scene older than 3.5 */
		s->noise_generator = e.version < 3.5 ? 1 : 2;
	eval_free(&e);
	return diag_error_count() > e.errors_at_start ? -1 : 0;
}
