/* csg.c: CSG programs on the host (csg.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "csg.h"
#include "diag.h"

void csg_push(csg_prog *p, int op, int arg)
{
	if (p->n == p->cap) {
		p->cap = p->cap ? 2 * p->cap : 16;
		p->ops = realloc(p->ops, p->cap * sizeof *p->ops);
		if (!p->ops) {
			fputs("eclat: out of memory\n", stderr);
			diag_exit(1);
		}
	}
	p->ops[p->n++] = csg_op(op, arg);
}

void csg_append(csg_prog *p, const int *src, int n, int shift)
{
	for (int i = 0; i < n; i++) {
		int op = csg_op_code(src[i]), arg = csg_op_arg(src[i]);
		csg_push(p, op, op == CSG_LEAF ? arg + shift : arg);
	}
}

int csg_depth(const int *ops, int n)
{
	int sp = 0, deepest = 0;
	for (int i = 0; i < n; i++) {
		int op = csg_op_code(ops[i]);
		if (op == CSG_LEAF || op == CSG_LEAF_BOXED)   /* lowering's programs have both */
			sp++;
		else if (op != CSG_NOT)
			sp -= csg_op_arg(ops[i]) - 1;
		deepest = sp > deepest ? sp : deepest;
	}
	return deepest;
}

bool csg_classify(const int *ops, int n, int k, bool (*inside)(void *ctx, int leaf), void *ctx, bool *flip)
{
	/* the stacks: with the point inside leaf k, outside it, and whether an
	 * entry holds leaf k */
	int depth = csg_depth(ops, n);
	bool *v1 = malloc(3 * (depth + 1) * sizeof *v1), *v0 = v1 + depth + 1, *has = v0 + depth + 1;
	if (!v1) {
		fputs("eclat: out of memory\n", stderr);
		diag_exit(1);
	}
	int sp = 0;
	for (int i = 0; i < n; i++) {
		int op = csg_op_code(ops[i]), arg = csg_op_arg(ops[i]);
		if (op == CSG_LEAF) {
			bool in = arg == k || (arg != CSG_NO_LEAF && inside(ctx, arg));
			v1[sp] = in;
			v0[sp] = arg == k ? false : in;
			has[sp++] = arg == k;
			continue;
		}
		if (op == CSG_NOT) {
			v1[sp - 1] = !v1[sp - 1];
			v0[sp - 1] = !v0[sp - 1];
			continue;
		}
		int base = sp - arg, held = -1;
		bool r1 = op == CSG_AND, r0 = op == CSG_AND;
		for (int j = base; j < sp; j++) {
			held = has[j] ? j : held;
			if (op == CSG_AND) {
				r1 = r1 && v1[j];
				r0 = r0 && v0[j];
			} else {
				r1 = r1 || v1[j];
				r0 = r0 || v0[j];
			}
		}
		if (op == CSG_UNION && held >= 0) {   /* a union keeps its parts' inner surfaces */
			r1 = v1[held];
			r0 = v0[held];
		}
		v1[base] = r1;
		v0[base] = r0;
		has[base] = held >= 0;
		sp = base + 1;
	}
	bool on = v1[0] != v0[0];
	*flip = !v1[0];
	free(v1);
	return on;
}

bool csg_inside(const int *ops, int n, bool (*inside)(void *ctx, int leaf), void *ctx)
{
	bool outside;   /* no leaf -1: the program's plain answer, which flip holds negated */
	csg_classify(ops, n, -1, inside, ctx, &outside);
	return !outside;
}

void csg_bounds(const int *ops, int n, int n_leaves, const double (*lo)[3], const double (*hi)[3],
                double out_lo[3], double out_hi[3])
{
	int depth = csg_depth(ops, n);
	double (*slo)[3] = malloc(2 * (depth + 1) * sizeof *slo), (*shi)[3] = slo + depth + 1;
	if (!slo) {
		fputs("eclat: out of memory\n", stderr);
		diag_exit(1);
	}
	int sp = 0;
	for (int i = 0; i < n; i++) {
		int op = csg_op_code(ops[i]), arg = csg_op_arg(ops[i]);
		if (op == CSG_LEAF) {
			for (int k = 0; k < 3; k++) {
				slo[sp][k] = arg < n_leaves ? lo[arg][k] : CSG_HUGE;
				shi[sp][k] = arg < n_leaves ? hi[arg][k] : -CSG_HUGE;
			}
			sp++;
			continue;
		}
		if (op == CSG_NOT) {   /* the outside of a bounded thing is unbounded */
			for (int k = 0; k < 3; k++) {
				slo[sp - 1][k] = -CSG_HUGE;
				shi[sp - 1][k] = CSG_HUGE;
			}
			continue;
		}
		int base = sp - arg;
		for (int j = base + 1; j < sp; j++)
			for (int k = 0; k < 3; k++) {
				if (op == CSG_AND) {
					slo[base][k] = fmax(slo[base][k], slo[j][k]);
					shi[base][k] = fmin(shi[base][k], shi[j][k]);
				} else {
					slo[base][k] = fmin(slo[base][k], slo[j][k]);
					shi[base][k] = fmax(shi[base][k], shi[j][k]);
				}
			}
		sp = base + 1;
	}
	memcpy(out_lo, slo[0], sizeof slo[0]);
	memcpy(out_hi, shi[0], sizeof shi[0]);
	free(slo);
}
