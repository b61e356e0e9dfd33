/* csg.h: CSG programs (kernels/shared.h, CSG_), as the evaluator builds them,
 * trace() classifies with them and lowering checks and bounds them; the
 * kernels run the same programs in kernels/csg.c. A program is a list of ints,
 * each an op in the top 8 bits and its operand below; its leaves are numbered
 * from 0. */
#ifndef ECLAT_CSG_H
#define ECLAT_CSG_H

#include <stdbool.h>

#include "../kernels/shared.h"

typedef struct {
	int *ops;
	int n, cap;
} csg_prog;

static inline int csg_op(int op, int arg)
{
	return op << CSG_OP_SHIFT | arg;
}
static inline int csg_op_code(int op)
{
	return op >> CSG_OP_SHIFT;
}
static inline int csg_op_arg(int op)
{
	return op & ((1 << CSG_OP_SHIFT) - 1);
}

#define CSG_NO_LEAF ((1 << CSG_OP_SHIFT) - 1)   /* a CSG_LEAF operand no leaf has: never inside */

/* Appends an op; exits with a message on out of memory. */
void csg_push(csg_prog *p, int op, int arg);
/* Appends the ops of src with its leaf numbers moved up by shift. */
void csg_append(csg_prog *p, const int *src, int n, int shift);

/* The deepest the program's stack gets. The functions below take programs of
 * any depth (the kernels' limit, CSG_STACK, is lowering's to check). */
int csg_depth(const int *ops, int n);

/* Whether the point of leaf k's surface is on the CSG's surface, the other
 * leaves answering inside(ctx, leaf); *flip when the CSG's inside is on the
 * leaf's outside there. kernels/csg.cl's csg_classify does the same. */
bool csg_classify(const int *ops, int n, int k, bool (*inside)(void *ctx, int leaf), void *ctx, bool *flip);

/* Whether a point is inside the CSG object, its leaves answering inside(ctx, leaf). */
bool csg_inside(const int *ops, int n, bool (*inside)(void *ctx, int leaf), void *ctx);

/* The program's box from its leaves' boxes (lo[i], hi[i] for the n_leaves
 * leaves; an operand past them is empty): an intersection's is the overlap of
 * its parts', a union's their union, an inverse's all space (+-CSG_HUGE). An
 * empty box has lo > hi. */
#define CSG_HUGE 1e30
void csg_bounds(const int *ops, int n, int n_leaves, const double (*lo)[3], const double (*hi)[3],
                double out_lo[3], double out_hi[3]);

#endif
