/* eval_bicubic.c: bicubic_patch { type T [flatness F] [u_steps U] [v_steps V]
 * [accuracy A] [uv_vectors ...] <P00>, <P01>, ... <P33> }, POV-Ray 3.7's Bezier
 * patch (Parse_Bicubic_Patch), cut into triangles here: 2^U by 2^V
 * quadrilaterals of the patch's parameters (POV-Ray's type 1 mesh; its type 0
 * subdivides as flat as flatness asks, to the same depths), each two
 * triangles on the diagonal from its (u0, v0) corner to its (u1, v1) one, with
 * the patch's own unit normal at every corner, as POV-Ray's
 * bezier_subpatch_intersect. The 16 points are four rows of four: P[i][j], i
 * along u and j along v. Every corner has POV-Ray's uv (the mesh's uv, which
 * the device interpolates across a triangle as POV-Ray interpolates the
 * parameters): the patch's parameters, v first, taken onto the quadrilateral
 * of uv_vectors (Compute_Texture_UV; the unit square when there is none). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

#define MAX_STEPS 8   /* 256 x 256 quadrilaterals */

/* The Bernstein weights of degree 3 at t, and their derivatives. */
static void bernstein(double t, double b[4], double d[4])
{
	double s = 1 - t;
	b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
	d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t, d[3] = 3 * t * t;
}

/* The patch's point at (u, v) and its normal there (the cross of its tangents). */
static void patch_at(const double P[4][4][3], double u, double v, double x[3], double n[3])
{
	double bu[4], du[4], bv[4], dv[4], tu[3] = { 0, 0, 0 }, tv[3] = { 0, 0, 0 };
	bernstein(u, bu, du);
	bernstein(v, bv, dv);
	x[0] = x[1] = x[2] = 0;
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++)
			for (int k = 0; k < 3; k++) {
				x[k] += bu[i] * bv[j] * P[i][j][k];
				tu[k] += du[i] * bv[j] * P[i][j][k];
				tv[k] += bu[i] * dv[j] * P[i][j][k];
			}
	n[0] = tu[1] * tv[2] - tu[2] * tv[1];
	n[1] = tu[2] * tv[0] - tu[0] * tv[2];
	n[2] = tu[0] * tv[1] - tu[1] * tv[0];
	double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	for (int k = 0; k < 3 && l > 0; k++)
		n[k] /= l;
}

/* POV-Ray's uv at the patch's parameters (u, v): (v, u) taken bilinearly onto
 * the quadrilateral st[4] (Compute_Texture_UV), st[0] at (0, 0), st[1] at
 * v = 1, st[2] at (1, 1), st[3] at u = 1. */
static void patch_uv(const double st[4][2], double u, double v, double uv[2])
{
	for (int k = 0; k < 2; k++) {
		double lo = st[0][k] + v * (st[1][k] - st[0][k]), hi = st[3][k] + v * (st[2][k] - st[3][k]);
		uv[k] = lo + u * (hi - lo);
	}
}

static void make_mesh(const double P[4][4][3], const double st[4][2], int su, int sv, scene_mesh *m, src_loc loc)
{
	int nu = 1 << su, nv = 1 << sv;
	*m = (scene_mesh){ .loc = loc };
	m->n_v = m->n_nrm = m->n_uv = (nu + 1) * (nv + 1);
	m->v = eval_xrealloc(NULL, (size_t)m->n_v * sizeof *m->v);
	m->nrm = eval_xrealloc(NULL, (size_t)m->n_nrm * sizeof *m->nrm);
	m->uv = eval_xrealloc(NULL, (size_t)m->n_uv * sizeof *m->uv);
	for (int i = 0; i <= nu; i++)   /* vertex i (nv + 1) + j at u = i / nu, v = j / nv */
		for (int j = 0; j <= nv; j++) {
			patch_at(P, (double)i / nu, (double)j / nv, m->v[i * (nv + 1) + j], m->nrm[i * (nv + 1) + j]);
			patch_uv(st, (double)i / nu, (double)j / nv, m->uv[i * (nv + 1) + j]);
		}
	m->face = eval_xrealloc(NULL, 2 * (size_t)nu * nv * sizeof *m->face);
	m->face_nrm = eval_xrealloc(NULL, 2 * (size_t)nu * nv * sizeof *m->face_nrm);
	m->face_uv = eval_xrealloc(NULL, 2 * (size_t)nu * nv * sizeof *m->face_uv);
	for (int i = 0; i < nu; i++)
		for (int j = 0; j < nv; j++) {
			int a = i * (nv + 1) + j, b = a + 1, c = a + nv + 1, d = c + 1;   /* (u0,v0) (u0,v1) (u1,v0) (u1,v1) */
			int t[2][3] = { { a, b, d }, { a, d, c } };
			for (int k = 0; k < 2; k++) {   /* a corner's normal and uv are its vertex's */
				memcpy(m->face_nrm[m->n_faces], t[k], sizeof t[k]);
				memcpy(m->face_uv[m->n_faces], t[k], sizeof t[k]);
				memcpy(m->face[m->n_faces++], t[k], sizeof t[k]);
			}
		}
}

/* uv_vectors <A>, <B>, <C>, <D>: the four corners of the patch's uv, which
 * end its keywords (POV-Ray reads nothing after them). */
static int uv_vectors(struct eval *e, struct cursor *c, const ast_node *item, double st[4][2])
{
	int err = 0;
	const ast_node *arg[4] = { item->kids[0] };
	for (int k = 1; k < 4 && !err; k++)
		if (!(arg[k] = eval_next_expr(c, &err))) {
			if (!err)
				eval_error(e, item->loc, "uv_vectors in a bicubic_patch needs four uv vectors");
			return -1;
		}
	for (int k = 0; k < 4; k++) {
		double v[3];
		if (!arg[k] || eval_expect_vector(e, arg[k], v))
			return -1;
		st[k][0] = v[0], st[k][1] = v[1];
	}
	return 0;
}

int eval_bicubic_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int err = 0, rc = 0;
	double type = 0, steps[2] = { 0, 0 }, unused, st[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
	const ast_node *item;
	while (rc == 0 && (item = eval_next(c, &err)) != NULL) {
		const ast_node *neg;
		const char *w = eval_word_item(item, &neg);
		if (item->kind == AST_ARG && item->kw == KW_UV_VECTORS) {
			rc = uv_vectors(e, c, item, st);
			break;
		}
		if (w && strcmp(w, AST_WORD_TYPE) == 0)
			rc = eval_word_float(e, c, item, neg, &type);
		else if (w && (strcmp(w, AST_WORD_FLATNESS) == 0 || strcmp(w, AST_WORD_ACCURACY) == 0))
			rc = eval_word_float(e, c, item, neg, &unused);
		else if (w && strcmp(w, AST_WORD_U_STEPS) == 0)
			rc = eval_word_float(e, c, item, neg, &steps[0]);
		else if (w && strcmp(w, AST_WORD_V_STEPS) == 0)
			rc = eval_word_float(e, c, item, neg, &steps[1]);
		else {
			eval_unget(c, item);
			break;
		}
	}
	if (rc || err)
		return -1;
	if (type < 0) {
		eval_error(e, b->loc, "undefined bicubic patch type %g (POV-Ray's error)", type);
		return -1;
	}
	if (type > 1)
		eval_warning(e, b->loc, "patch type %g no longer supported; using type 1 (POV-Ray's warning)", type);
	double P[4][4][3];
	for (int i = 0; i < 16; i++) {
		const ast_node *p = eval_next_expr(c, &err);
		if (!p) {
			if (!err)
				eval_error(e, b->loc, "a bicubic_patch needs 16 control points, not %d", i);
			return -1;
		}
		if (eval_expect_vector(e, p, P[i / 4][i % 4]))
			return -1;
	}
	int su = (int)fmin(fmax(steps[0], 0), MAX_STEPS), sv = (int)fmin(fmax(steps[1], 0), MAX_STEPS);
	scene_mesh m;
	make_mesh(P, (const double (*)[2])st, su, sv, &m, b->loc);
	o->mesh = scene_add_mesh(e->s, &m);
	return 0;
}
