/* lower_csg_program.c: a CSG program as the kernels run it (kernels/csg.cl's
 * csg_classify). The evaluator writes a difference or an intersection of many
 * parts as a chain, ((A B AND) C AND) ..., whose every prefix holds the first
 * part; here chains of one associative op are rebalanced into halves, and a
 * half whose leaves all have their insides within their boxes is headed by a
 * CSG_SKIP, which the kernels take when no leaf of it has a box that holds
 * the point: then each of its leaves is outside, and the half's value is the
 * one it has with all of them outside, known here. A classification of a
 * point of a box less 100 cylinders reads a few dozen ints instead of 300.
 *
 *   csg_prog out;
 *   if (lower_csg_program(p.ops, p.n, boxes, n_seen, &out) > CSG_STACK) ...   use p
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "csg.h"
#include "lower.h"

/* A half smaller than this many ops is cheaper read than skipped. */
#define SKIP_MIN_OPS 8

static void *alloc(size_t n)
{
	void *p = calloc(1, n ? n : 1);
	if (!p) {
		fputs("eclat: out of memory\n", stderr);
		diag_exit(1);
	}
	return p;
}

struct node {
	int op, arg;          /* a leaf's op and number, CSG_NOT, or an associative op */
	struct node **kid;
	int n_kids, height;
};

/* The tree of the postfix program, in nodes (one an op at most), chains of
 * one op (AND, OR, UNION: each associative, a union's keeping of its parts'
 * inner surfaces too) made one node with all their parts; its root, or NULL
 * when the program is not one formula or nests too deep for emit_node's
 * recursion (the caller then keeps the program as it is). */
#define MAX_HEIGHT 1000

static struct node *parse(const int *ops, int n, struct node *nodes)
{
	struct node **stack = alloc((n + 1) * sizeof *stack);
	int sp = 0, ok = 1;
	for (int i = 0; i < n && ok; i++) {
		int op = csg_op_code(ops[i]), arg = csg_op_arg(ops[i]);
		struct node *t = &nodes[i];
		t->op = op;
		t->arg = arg;
		int take = op == CSG_LEAF || op == CSG_LEAF_BOXED ? 0 : op == CSG_NOT ? 1 : arg;
		if (take > sp || take < 0) {
			ok = 0;
			break;
		}
		int parts = 0;
		for (int j = sp - take; j < sp; j++)
			parts += stack[j]->op == op && op != CSG_NOT ? stack[j]->n_kids : 1;
		t->kid = alloc(parts * sizeof *t->kid);
		t->height = 1;
		for (int j = sp - take; j < sp; j++) {
			struct node *k = stack[j];
			if (k->op == op && op != CSG_NOT) {   /* its parts become t's: k is left empty */
				memcpy(t->kid + t->n_kids, k->kid, k->n_kids * sizeof *t->kid);
				t->n_kids += k->n_kids;
				t->height = t->height > k->height ? t->height : k->height;
				free(k->kid);
				k->kid = NULL;
				k->n_kids = 0;
			} else {
				t->kid[t->n_kids++] = k;
				t->height = t->height > k->height + 1 ? t->height : k->height + 1;
			}
		}
		ok = t->height <= MAX_HEIGHT;
		sp -= take;
		stack[sp++] = t;
	}
	struct node *root = ok && sp == 1 ? stack[0] : NULL;
	free(stack);
	return root;
}

struct emit {
	const dev_prim *boxes;
	int n_seen;
	double volume;        /* of the box of all the leaves rays may meet */
};

/* What a piece of the program knows of itself: its leaves' bits (k % 64),
 * their box, whether every leaf is one rays may meet and whose inside lies
 * within its box, its value with all its leaves outside and its depth. */
struct facts {
	unsigned long long mask;
	double lo[3], hi[3];
	int boxed, value, depth;
};

static double comp(const float4 *v, int k)
{
	return k == 0 ? v->x : k == 1 ? v->y : v->z;
}

static void push_raw(csg_prog *p, int v)
{
	csg_push(p, 0, 0);
	p->ops[p->n - 1] = v;
}

static void join(struct facts *f, const struct facts *g)
{
	f->mask |= g->mask;
	for (int k = 0; k < 3; k++) {
		f->lo[k] = fmin(f->lo[k], g->lo[k]);
		f->hi[k] = fmax(f->hi[k], g->hi[k]);
	}
	f->boxed &= g->boxed;
	f->depth = f->depth > g->depth ? f->depth : g->depth;
}

static double volume(const double lo[3], const double hi[3])
{
	double v = 1;
	for (int k = 0; k < 3; k++)
		v *= hi[k] > lo[k] ? hi[k] - lo[k] : 0;
	return v;
}

static void emit_node(const struct emit *e, const struct node *t, csg_prog *out, struct facts *f);

/* Parts kid[first .. first + count - 1] of an associative node, in halves,
 * each half of enough ops whose leaves' boxes fill less than half of the
 * CSG's headed by a CSG_SKIP. */
static void emit_parts(const struct emit *e, const struct node *t, int first, int count, csg_prog *out,
                       struct facts *f)
{
	if (count == 1) {
		emit_node(e, t->kid[first], out, f);
		return;
	}
	csg_prog body = { 0 };
	struct facts g;
	if (count <= 3) {   /* one op for a few parts */
		emit_node(e, t->kid[first], &body, f);
		for (int i = 1; i < count; i++) {
			emit_node(e, t->kid[first + i], &body, &g);
			g.depth += i;
			join(f, &g);
			f->value = t->op == CSG_AND ? f->value && g.value : f->value || g.value;
		}
		csg_push(&body, t->op, count);
	} else {
		int half = count / 2;
		emit_parts(e, t, first, half, &body, f);
		emit_parts(e, t, first + half, count - half, &body, &g);
		g.depth += 1;
		join(f, &g);
		f->value = t->op == CSG_AND ? f->value && g.value : f->value || g.value;
		csg_push(&body, t->op, 2);
	}
	if (f->boxed && body.n >= SKIP_MIN_OPS && body.n < 1 << (CSG_OP_SHIFT - 2) &&
	    volume(f->lo, f->hi) < 0.5 * e->volume) {   /* n << 1 | v in the operand */
		csg_push(out, CSG_SKIP, body.n << 1 | f->value);
		push_raw(out, (int)(unsigned)(f->mask & 0xffffffffu));
		push_raw(out, (int)(unsigned)(f->mask >> 32));
	}
	for (int i = 0; i < body.n; i++)
		push_raw(out, body.ops[i]);
	free(body.ops);
}

static void emit_node(const struct emit *e, const struct node *t, csg_prog *out, struct facts *f)
{
	if (t->op == CSG_LEAF || t->op == CSG_LEAF_BOXED) {
		*f = (struct facts){ 0, { INFINITY, INFINITY, INFINITY }, { -INFINITY, -INFINITY, -INFINITY }, 1, 0, 1 };
		if (t->arg != CSG_NO_LEAF) {   /* CSG_NO_LEAF: outside everywhere */
			const dev_prim *b = &e->boxes[t->arg];
			for (int k = 0; k < 3; k++) {
				f->lo[k] = fmin(comp(&b->a, k), comp(&b->b, k));
				f->hi[k] = fmax(comp(&b->a, k), comp(&b->b, k));
			}
			f->mask = 1ull << (t->arg & 63);
			f->boxed = t->op == CSG_LEAF_BOXED && t->arg < e->n_seen;
		}
		csg_push(out, t->op, t->arg);
		return;
	}
	if (t->op == CSG_NOT) {
		emit_node(e, t->kid[0], out, f);
		f->value = !f->value;
		csg_push(out, CSG_NOT, 0);
		return;
	}
	emit_parts(e, t, 0, t->n_kids, out, f);
}

int lower_csg_program(const int *ops, int n, const dev_prim *boxes, int n_seen, csg_prog *out)
{
	memset(out, 0, sizeof *out);
	struct node *nodes = alloc((n + 1) * sizeof *nodes), *root = parse(ops, n, nodes);
	if (!root) {
		for (int i = 0; i < n; i++)
			free(nodes[i].kid);
		free(nodes);
		return CSG_STACK + 1;
	}
	struct emit e = { boxes, n_seen, 0 };
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	for (int j = 0; j < n_seen; j++)
		for (int k = 0; k < 3; k++) {
			lo[k] = fmin(lo[k], fmin(comp(&boxes[j].a, k), comp(&boxes[j].b, k)));
			hi[k] = fmax(hi[k], fmax(comp(&boxes[j].a, k), comp(&boxes[j].b, k)));
		}
	e.volume = volume(lo, hi);
	struct facts f;
	emit_node(&e, root, out, &f);
	for (int i = 0; i < n; i++)
		free(nodes[i].kid);
	free(nodes);
	return f.depth;
}
